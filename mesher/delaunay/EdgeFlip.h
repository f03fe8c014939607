#pragma once
// Edge flip (diagonal swap) of two adjacent triangles and the flip criteria of thesis
// sec. 4.2 in metric space (coordinates transformed by a constant M, PlaneTransform.h).
//
// Naming: edge i of t is (b, c) with a = v[i], b = v[i+1], c = v[i+2]; u is the
// neighbour across it and d its vertex opposite the edge. The flip replaces the diagonal
// (b, c) of the quadrilateral a-b-d-c by (a, d): t becomes (a, b, d), u becomes (a, d, c).
//
// Check, then change (STYLE.md §6): canFlip decides legality and returns a plan; flip
// applies it. Legal iff u exists, the edge is not constrained, and the quadrilateral is
// strictly convex, i.e. both new triangles are counter-clockwise (exact orient2d > 0).
//
// Criteria (whether the flip improves the triangulation, evaluated on M·x):
//   violatesEmptyCircle  — sec. 4.2.1: d strictly inside the circumcircle of (a, b, c),
//                          exact incircle on the transformed doubles;
//   violatesInnerAngles  — sec. 4.2.2: the angles at a and d opposite the edge sum to
//                          more than π (floating point, Cline–Renka form
//                          sin(α + δ) < 0 with unnormalised sines and cosines).
// restoreDelaunay applies Lawson flips from a set of edges until the criterion holds on
// every edge reached or a swap limit is hit (thesis Table 4.1: the number of swaps per
// inserted point is limited since a variable metric may make flipping cycle).
#include <cstddef>
#include <span>

#include "mesher/delaunay/PlaneTransform.h"
#include "mesher/delaunay/Triangulation2d.h"

namespace aniso::del2d {

struct FlipPlan {
  bool legal = false;
  TriId t, u;
  int i = -1, j = -1;  ///< the edge's local index in t and in u
  VertexId a, b, c, d;
};

/// Check: whether edge i of the live triangle t can be flipped.
FlipPlan canFlip(const Triangulation2d& tri, TriId t, int i);
/// Change: applies a legal plan (throws MeshingError for an illegal one). t and u keep
/// their ids; constrained bits follow their edges; vertex→triangle links are updated.
void flip(Triangulation2d& tri, const FlipPlan& plan);

/// Empty-circumcircle criterion on M·x for edge i of t (false without a neighbour).
bool violatesEmptyCircle(const Triangulation2d& tri, TriId t, int i, const PlaneTransform& m);
/// Inner-angle criterion on M·x for edge i of t (false without a neighbour).
bool violatesInnerAngles(const Triangulation2d& tri, TriId t, int i, const PlaneTransform& m);

enum class FlipCriterion { EmptyCircle, InnerAngles };

struct FlipStats {
  std::size_t checked = 0;  ///< edges tested
  std::size_t flipped = 0;
  bool limitReached = false;
};

/// Lawson flips starting from every edge of the given triangles: an unconstrained edge
/// violating the criterion is flipped when legal, and the four outer edges of the pair
/// are queued. Stops after maxFlips flips.
FlipStats restoreDelaunay(Triangulation2d& tri, std::span<const TriId> start, const PlaneTransform& m,
                          FlipCriterion criterion = FlipCriterion::EmptyCircle,
                          std::size_t maxFlips = 1000000);

}  // namespace aniso::del2d
