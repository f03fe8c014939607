#pragma once
// unfoldFace — the last step of the face mesher: removes the triangles that are not
// upright on the surface (SurfaceLift.h) which the guarded operators could not avoid —
// triangles of the boundary triangulation that the refinement could not split (three
// nearly collinear rim nodes standing across the face; a triangle wrapping around a pole).
//
// Rounds over the folded triangles, in index order (deterministic):
//   - flip an unconstrained edge of the triangle when both new triangles are
//     counter-clockwise in (u, v) (del2d::canFlip) and upright: the folded count drops;
//   - else move a free corner (not fixed, not on the triangulation's border) to the
//     (u, v) centroid of its ring when its whole star stays counter-clockwise and upright;
//   - else split a neighbour at a new node and flip the common edge (a sliver of three
//     rim nodes, convex in (u, v) but not on the surface, whose plain flip would fold).
// Until no folded triangle is left, a round changes nothing, or maxRounds. Every change
// lowers the number of folded triangles (its new triangles are all upright). Never changes
// constrained edges or fixed vertices; the result is a valid triangulation of the same
// domain (with the split nodes added as interior vertices). Returns the number of folded triangles left.
#include <cstdint>
#include <vector>

#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/surface/face/SurfaceLift.h"

namespace aniso::face {

struct UnfoldFaceStats {
  int foldedBefore = 0, foldedAfter = 0, flips = 0, moves = 0, splits = 0;
};

UnfoldFaceStats unfoldFace(del2d::Triangulation2d& tri, const SurfaceLift& lift,
                           const std::vector<std::uint8_t>& fixed, int maxRounds = 8);

/// The live triangles that are not upright, in index order (empty when the lift is inactive).
std::vector<del2d::TriId> notUpright(const del2d::Triangulation2d& tri, const SurfaceLift& lift);

}  // namespace aniso::face
