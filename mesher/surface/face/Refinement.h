#pragma once
// Insertion of inner nodes (thesis sec. 4.5) into the constrained triangulation of a face,
// in the metric M = M_s M_p of its control space.
//
// Quality (eq. 4.1): q(K) = S_oI / S_oK with M taken at the centroid of K (FaceMetric.h).
// When q(K) ≥ q_t but an unconstrained edge of K has metric length > maxEdgeMetricLength
// (the mean of its lengths in the metrics of its two end vertices, an approximation of
// the midpoint rule; cached per vertex), q(K) is set to 0.95 q_t so that K is refined.
// Boundary (constrained) edges are never split, so their length does not make K bad.
//
// Loop: every triangle with q < q_t is in a heap (worst first; ties by slot index, so the
// order is deterministic); stale entries (slot freed or reused) are skipped. For the worst
// triangle K a point is chosen by the mixed method of Table 4.4:
//   • MLE (q(K) < mleToCcsQuality): the middle of the longest edge of K in M(K); when
//     that edge is constrained the insertion is cancelled (boundary edges never split);
//   • CCS otherwise: the circumcentre of K in M(K), located by a straight walk from K
//     (VisibleWalk.h); when it is outside the face or behind a contour, MLE instead.
// The point p is inserted by Bowyer–Watson with M(p) (del2d::planInsertion, walk started at
// the triangle found), after the cancellation rules of sec. 4.5, all checked on the plan
// before anything changes:
//   • the kernel refuses p (duplicate, on a constrained edge, outside);
//   • K is not in the cavity of p (the metric varies too much between K and p: K would
//     survive the insertion);
//   • p is closer than minVertexDistance (in M(p)) to a vertex of the cavity boundary;
//   • p is closer than minContourDistance (in M(p)) to a constrained edge of the cavity.
// A cancelled triangle leaves the heap (it comes back only if an insertion rebuilds it).
// The new triangles are evaluated and pushed when bad.
// With innerAngles (sec. 4.2.2) p splits the triangle(s) containing it and edges are then
// swapped by the inner-angles criterion in M(p) (InnerAngleSwaps.h, at most
// maxSwapsPerPoint swaps); the cancellation rules check the split triangles' vertices, the
// metric-jump rule does not apply, and every swapped triangle is re-evaluated too.
//
// Termination on any input: at most insertionLimitFactor × NT_p + insertionLimitExtra
// insertions, NT_p the predicted final element count of eq. 6.2 (sum of metric areas of
// the initial triangles over √3/4, each area taken with the largest det M of its centroid
// and vertices); reaching it sets limitReached. Every pop either inserts or discards an
// entry, and entries are only pushed for new triangles, so the loop ends.
//
// Precondition: tri holds only the face (outside removed), its boundary edges constrained.
// The result is a valid triangulation (Validate2d.h) conforming to the same constrained
// edges. Allocation: the heap and the per-slot arrays grow with the mesh only.
#include <cstddef>
#include <functional>

#include "mesher/core/Cancel.h"
#include "mesher/control/ControlSpace2d.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/surface/face/SurfaceLift.h"

namespace aniso::face {

struct RefineOptions {
  double qualityThreshold = 0.58;    ///< q_t
  double maxEdgeMetricLength = 1.5;  ///< l_M above which an edge makes its triangle bad
  double mleToCcsQuality = 0.3;      ///< MLE below this q(K), CCS above
  double minVertexDistance = 0.5;    ///< metric distance to a cavity vertex below which p is cancelled
  double minContourDistance = 0.3;   ///< metric distance to a constrained cavity edge below which p is cancelled
  double insertionLimitFactor = 4;   ///< × NT_p
  std::size_t insertionLimitExtra = 1000;
  std::size_t maxWalkSteps = 4096;   ///< CCS location walk
  /// Retriangulation by the inner-angles criterion (sec. 4.2.2, InnerAngleSwaps.h) instead
  /// of the empty circumcircle; the metric-jump rule then does not apply.
  bool innerAngles = false;
  std::size_t maxSwapsPerPoint = 50;  ///< inner-angles swaps per inserted node (Table 4.1)
  /// Frontal phase first (FrontalPoint.h, Rebay's frontal Delaunay): only bad triangles on
  /// the front — next to a contour or an accepted triangle — are refined, each by the
  /// frontal point on its front edge (the MLE/CCS point when that is cancelled); when the
  /// front is exhausted the remaining bad triangles get the mixed MLE/CCS method. Far more
  /// regular meshes than MLE/CCS alone (docs/measurements.md). false: the thesis' MLE/CCS
  /// method only.
  bool frontal = true;
  /// Receives the predicted final triangle count (thesis 6.5): eq. 6.2 once the initial
  /// triangles are evaluated, then eq. 6.1, NT_c · q_t / q(K_root), every
  /// predictionInterval heap pops while refining. May be empty.
  std::function<void(double)> onPrediction;
  std::size_t predictionInterval = 4096;
  /// The face's surface (may be null or inactive): an insertion whose new triangles would
  /// not all be upright on the surface (SurfaceLift.h) is cancelled, and a triangle that is
  /// not upright counts as the worst (q = 0), so it is refined first.
  const SurfaceLift* lift = nullptr;
  /// Checked every few hundred heap pops (Cancel.h); null: never stops.
  const CancelToken* cancel = nullptr;
};

struct RefineStats {
  std::size_t inserted = 0, cancelled = 0;
  std::size_t mle = 0, ccs = 0, ccsFallbacks = 0;  ///< insertions by method; CCS → MLE fallbacks
  std::size_t frontal = 0;                         ///< insertions at a frontal point
  std::size_t swaps = 0;                           ///< inner-angles mode
  /// Cancellations by rule.
  std::size_t cancelBoundaryEdge = 0, cancelRefused = 0, cancelMetricJump = 0, cancelNearVertex = 0,
              cancelNearContour = 0;
  /// Insertions refused with the fold guard on (RefineOptions::lift): the cavity could not
  /// be pruned to new triangles that are upright on the surface and star-shaped.
  std::size_t cancelFold = 0;
  double predictedTriangles = 0;  ///< NT_p (eq. 6.2)
  std::size_t insertionLimit = 0;
  bool limitReached = false;
};

RefineStats refineFace(del2d::Triangulation2d& tri, const ControlSpace2d& cs, const RefineOptions& options = {});

}  // namespace aniso::face
