#pragma once
// Retriangulation after an insertion by the inner-angles criterion (thesis sec. 4.2.2,
// Fig. 4.3): the new node splits its containing triangle (or the two triangles of the edge
// it lies on) — plan it with innerAnglesConflict(), which puts no further triangle in the
// cavity — and then the edges of the new triangles and of their neighbours are swapped
// while the inner-angles criterion on M·x (M the metric of the inserted node, constant)
// prefers the other diagonal (del2d::violatesInnerAngles), at most maxFlips swaps per
// inserted node (Table 4.1: limiting the swaps costs neither quality nor time, and a
// variable metric could otherwise make the swapping cycle). Constrained edges never swap.
//
// Unlike del2d::restoreDelaunay this reports every triangle it changed, so that the
// refinement can re-evaluate them; the caller's buffers are reused (no allocation once
// grown).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/PlaneTransform.h"
#include "mesher/delaunay/Triangulation2d.h"

namespace aniso::face {

/// The conflict test of the inner-angles insertion: no triangle beyond the containing one(s).
const del2d::ConflictTest& innerAnglesConflict();

/// Swaps from the edges of `start`; appends each triangle changed by a swap to `changed`
/// (possibly repeated). Returns the number of swaps.
std::size_t innerAngleSwaps(del2d::Triangulation2d& tri, std::span<const del2d::TriId> start,
                            const del2d::PlaneTransform& m, std::size_t maxFlips,
                            std::vector<std::uint32_t>& stack, std::vector<del2d::TriId>& changed);

}  // namespace aniso::face
