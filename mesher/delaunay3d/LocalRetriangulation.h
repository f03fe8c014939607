#pragma once
// replaceTets — the common "change" step of the flips T23, T32, T44 (thesis sec. 5.2.2):
// swaps a small set of tetrahedra for another triangulation of the same polyhedron.
// The flips' can*() functions decide legality (geometry, constrained faces); this only
// rewires adjacency, so every flip shares one tested implementation.
#include <array>
#include <span>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

inline constexpr std::size_t kMaxLocalTets = 16;  // 2 per tet of an edge ring of 8 (sliver Steiner points)

/// Replaces `oldTets` (distinct live tets, at most kMaxLocalTets) by tets with the vertex
/// quadruples `newTets` (at most kMaxLocalTets, each positively oriented — not checked
/// here), writing their ids to `out` (same size as newTets). The boundary of the new set
/// must be exactly the boundary of the old set (same vertex triples); faces on it keep
/// their outer neighbours and constrained bits, faces inside are unconstrained. Vertex→tet
/// references of the touched vertices are updated. Throws MeshingError before changing
/// anything when the boundaries do not match.
void replaceTets(TetMesh& mesh, std::span<const TetId> oldTets,
                 std::span<const std::array<VertexId, 4>> newTets, std::span<TetId> out);

/// Orientation of the quadruple with the exact predicate (> 0: positively oriented).
double orientation(const TetMesh& mesh, const std::array<VertexId, 4>& v);

}  // namespace aniso::del3d
