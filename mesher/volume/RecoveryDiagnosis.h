#pragma once
// Evidence for a boundary entity that recovery (BoundaryRecovery.h) left missing: the
// local configuration in a few numbers, so that a failure can be told apart as a thin
// solid, a nearly flat surface triangle or a cospherical / coplanar cluster. Read-only.
//
// For a missing edge (a, b): its length L, the pipe (faces pierced, edges crossed, or
// degenerate — a vertex on the segment), how many of the crossing entities are
// constrained boundary faces or boundary edges, and the nearest other boundary node to
// the segment (distance / L). For a missing triangle: the same over its pipe, plus its
// shape (area / longest edge^2, 0.43 for the equilateral one) and whether its edges are
// present. Thesis sec. 5.4 (table 5.4 names the same counts per phase).
#include <array>
#include <functional>
#include <string>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::volume {

/// True for a kernel vertex that is a boundary node of the solid.
using IsBoundaryVertex = std::function<bool(del3d::VertexId)>;
/// True for a vertex pair that is a boundary edge of the solid.
using IsBoundaryEdge = std::function<bool(del3d::VertexId, del3d::VertexId)>;

std::string describeMissingEdge(const del3d::TetMesh& mesh, del3d::VertexId a, del3d::VertexId b,
                                const IsBoundaryVertex& boundaryVertex, const IsBoundaryEdge& boundaryEdge);

std::string describeMissingTriangle(const del3d::TetMesh& mesh, const std::array<del3d::VertexId, 3>& t,
                                    const IsBoundaryVertex& boundaryVertex, const IsBoundaryEdge& boundaryEdge);

}  // namespace aniso::volume
