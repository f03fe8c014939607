#pragma once
// Edge removal — the edge flips of thesis sec. 5.2.2 "extended to cases with more than
// three tetrahedra incident to an edge": the n tetrahedra around an interior edge (a, b)
// (closed ring c0..c(n-1)) are replaced by the 2(n-2) tetrahedra joining a and b to a
// triangulation of the ring polygon. n = 3 is T32, n = 4 is T44; here the polygon is
// triangulated as a fan from one ring vertex c_s (all triangulations for n <= 5, 6 of the
// 14 for n = 6). Check, then change (STYLE.md §6): canRemoveEdge decides and plans,
// applyPlan (LocalChange.h) applies it through del3d::replaceTets.
#include <array>
#include <vector>

#include "mesher/delaunay3d/LocalRetriangulation.h"
#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::volume {

/// Largest ring handled: 2(n-2) new tets must fit in del3d::kMaxLocalTets.
inline constexpr int kMaxRemovalRing = 6;

struct LocalPlan {
  std::vector<del3d::TetId> oldTets;
  std::vector<std::array<del3d::VertexId, 4>> newTets;
  /// The vertices of oldTets when planned: an undo elsewhere may give the same tets other
  /// ids, so a plan is applied only while these still match (LocalChange.h).
  std::vector<std::array<del3d::VertexId, 4>> oldQuads;
};

/// True when the edge joining local vertices i and j of the live tet t is interior (closed
/// ring of 3..kMaxRemovalRing tets), no face around it is constrained, and the fan from
/// ring vertex `fan` (0 <= fan < n) gives 2(n-2) positively oriented tets (exact
/// orient3d). Fills *plan. Returns false for fan >= n.
bool canRemoveEdge(const del3d::TetMesh& mesh, del3d::TetId t, int i, int j, int fan, LocalPlan* plan);

/// Size of the closed ring around the edge (i, j) of t, or -1 when open or larger than
/// kMaxRemovalRing.
int removalRingSize(const del3d::TetMesh& mesh, del3d::TetId t, int i, int j);

}  // namespace aniso::volume
