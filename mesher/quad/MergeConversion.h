#pragma once
// Conversion to quadrilaterals by merging triangles (thesis 4.7.2, alg. 4.4, fig. 4.12),
// driven by the conversion front (4.7.1, FrontRank.h):
//   - every front edge is ranked by eq. 4.4 and kept in a heap; the lowest rank is taken
//     first (ties by element id and edge, so the result is deterministic);
//   - its triangle is merged with the neighbour across one of its two other edges that
//     gives the better quad (metric scaled Jacobian, QuadShape.h); a quad below
//     minQuality, or not strictly convex, is never formed;
//   - a merge that would leave an odd component of the unconverted region (RegionParity.h)
//     is replaced by the odd-cycle split (OddSplit.h): the neighbour split at its centroid
//     when the trouble comes from the neighbour's apex, the shared edge split at its
//     midpoint when it comes from the base triangle's apex; when it cannot be avoided the edge is put back with a higher rank
//     (at most maxDeferrals times) and then merged anyway — the odd component then keeps
//     one triangle, which TriangleTransport.h pairs up later;
//   - the new quad's edges join the front one level up, and the front edges around its
//     corners are reclassified.
// With morphing (method Morph or Mixed, alg. 4.3 and 4.5) the chosen front edges first try
// a morphing step; what it cannot do is merged as above.
// Triangles that no front edge could merge stay triangles.
#include <array>

#include "mesher/core/MeshOptions.h"
#include "mesher/quad/FrontRank.h"
#include "mesher/quad/MorphStep.h"

namespace aniso::quad {

struct MergeOptions {
  double minQuality = 0.1;  ///< least scaled Jacobian (QuadShape.h elementQuality) of a merged quad
  int maxDeferrals = 6;
  FrontWeights weights;
  /// Merge: every quad by merging. Morph: every quad by morphing (MorphStep.h), merging
  /// where a morphing step fails. Mixed (alg. 4.3): morphing where the front edge is near
  /// the boundary (level ≤ nearBoundaryLevels) or the metric gradation along it is low
  /// (≤ lowGradation, VertexMetrics::gradation), merging elsewhere.
  QuadMethod method = QuadMethod::Merge;
  int nearBoundaryLevels = 2;
  double lowGradation = 1.1;
  MorphOptions morph;
};

struct MergeStats {
  int quads = 0;
  int oddSplits = 0;
  int edgeSplits = 0;  ///< odd-cycle repairs by splitting the shared edge (apex on the front)
  int forcedOdd = 0;  ///< merges that left an odd region component
  int deferred = 0;
  int rejected = 0;   ///< front edges whose triangle had no legal merge then
  int triangles = 0;  ///< live triangles left
  int morphed = 0;    ///< of the quads, formed by morphing
  int seams = 0;      ///< seams closed by morphing (FrontSeam.h)
  int transitionSeams = 0;   ///< TransitionSeam.h
  int transitionSplits = 0;  ///< TransitionSplit.h
  std::array<int, 7> morphFailures{};  ///< failed morphing steps by MorphFailure
};

MergeStats mergeFront(QuadMesh2d& mesh, VertexMetrics& metrics, const MergeOptions& options = {});

}  // namespace aniso::quad
