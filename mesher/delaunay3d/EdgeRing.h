#pragma once
// Ring of tetrahedra around an edge (needed by the edge flips T32/T44 of thesis sec.
// 5.2.2 and by every edge-based quality operator of sec. 5.6).
#include <span>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

/// The tetrahedra around edge (a, b) in rotational order, with their "apex" vertices:
/// tets[m] contains a, b, apex[m] and apex[m+1] (indices mod tets.size() when closed);
/// tets[m] and tets[m+1] share the face (a, b, apex[m+1]). For a closed ring
/// apex.size() == tets.size(); for an open one (the edge is on the hull) the walk starts
/// and ends at hull faces and apex.size() == tets.size() + 1.
struct EdgeRing {
  VertexId a, b;
  std::vector<TetId> tets;
  std::vector<VertexId> apex;
  bool closed = false;
};

/// Fills `ring` with the tets around the edge joining local vertices i and j (i != j) of
/// the live tet t. Reuses ring's storage. The mesh must have symmetric adjacency.
/// Throws MeshingError if the rotation does not close after 10^6 steps (corrupt mesh).
void edgeRing(const TetMesh& mesh, TetId t, int i, int j, EdgeRing& ring);

/// Allocation-free variant for small closed rings (flips): fills tets[0..n) and apex[0..n)
/// as above, starting at t, and returns n; returns -1 when the ring is open or has more
/// than tets.size() tets (apex.size() must equal tets.size()).
int closedEdgeRing(const TetMesh& mesh, TetId t, int i, int j, std::span<TetId> tets,
                   std::span<VertexId> apex);

}  // namespace aniso::del3d
