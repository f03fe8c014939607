#pragma once
// Recovery of the boundary edges missing from the triangulation of the boundary nodes
// (thesis sec. 4.4, constraining phase: "by swapping of edges which for 2D triangulation is
// trivial and guaranteed to succeed"), by the edge-swapping algorithm of Sloan (1993,
// "A fast algorithm for generating constrained Delaunay triangulations", steps 3–4; also
// Anglada 1997):
//   1 (check, nothing changes) walk from a along the segment a→b with exact orient2d and
//     list the edges it crosses properly. A vertex exactly on the open segment, or a
//     crossed edge that is already constrained, makes the edge unrecoverable without
//     changing the boundary (the loops are not a planar straight-line graph in (u, v)):
//     reported, nothing changed.
//   2 (change) repeatedly take a crossing edge; when its quadrilateral is strictly convex
//     flip it, and queue the new diagonal again if it still crosses a→b, otherwise
//     remember it as new; a non-convex one goes back to the queue. For a PSLG this always
//     terminates with a→b present; a guard on the number of iterations turns any other
//     outcome into Failed (the triangulation stays valid).
// recoverBoundaryEdges runs the phase for a face: first every boundary edge already
// present is constrained (their count gives FaceMeshStats::missingBoundaryEdges), then each
// missing one is recovered and constrained at once, and the new edges around it are made
// Delaunay again (Lawson flips, sec. 4.2.1, metric at the edge's midpoint; constrained
// edges never flip).
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/surface/face/BoundaryTriangulation.h"

namespace aniso::face {

enum class RecoveryStatus {
  Present,             ///< a→b was already an edge
  Recovered,           ///< made present by flips
  VertexOnSegment,     ///< `blocker` lies on the open segment a→b (nothing changed)
  CrossesConstrained,  ///< the constrained edge (crossA, crossB) crosses a→b (nothing changed)
  Failed,              ///< iteration guard reached (the triangulation is still valid)
};

struct EdgeRecovery {
  RecoveryStatus status = RecoveryStatus::Failed;
  del2d::VertexId blocker, crossA, crossB;
  std::size_t crossings = 0;  ///< edges crossed by a→b initially
  std::size_t flips = 0;
  /// Recovered: the edges made by the flips other than a→b (for Delaunay restoration).
  std::vector<std::pair<del2d::VertexId, del2d::VertexId>> newEdges;
};

/// Makes {a, b} an edge of tri (a ≠ b, both vertices of live triangles, inside a
/// triangulation whose region contains the segment: the box triangulation). Does not
/// constrain it.
EdgeRecovery recoverEdge(del2d::Triangulation2d& tri, del2d::VertexId a, del2d::VertexId b);

struct BoundaryRecoveryStats {
  std::size_t missing = 0, recovered = 0, flips = 0;
};

/// The phase described above for every loop edge k → next[k] of the boundary (vertexOf from
/// triangulateBoundary, all valid). Returns the problems (edges that could not be recovered,
/// naming their nodes and what is in the way); stats may be null.
std::vector<std::string> recoverBoundaryEdges(del2d::Triangulation2d& tri, const FlatBoundary& boundary,
                                              const std::vector<del2d::VertexId>& vertexOf,
                                              const ControlSpace2d& cs, BoundaryRecoveryStats* stats = nullptr);

}  // namespace aniso::face
