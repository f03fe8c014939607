#pragma once
// The odd-cycle split of the merging conversion (thesis 4.7.2, fig. 4.12(c)): when merging
// the base triangle with its neighbour would close a front cycle with an odd number of
// edges (the neighbour's apex is on the front), the neighbour is split into three
// triangles at its centroid and the base triangle is merged with the part sharing its edge:
// the quad's fourth corner is then the new inner vertex, which touches no front, so no
// cycle is split and the region keeps its triangle count.
#include "mesher/quad/QuadShape.h"

namespace aniso::quad {

struct OddSplitResult {
  bool done = false;
  int quad = kNone;  ///< the new quad (base triangle + the part of the split neighbour)
};

/// Base triangle t1, neighbour t2 across t1's edge j. Checks first: the three parts and the
/// quad must be strictly convex and counter-clockwise and the quad's metric scaled
/// Jacobian at least minQuality; otherwise nothing changes.
OddSplitResult splitAndMerge(QuadMesh2d& mesh, VertexMetrics& metrics, int t1, int j, double minQuality);

/// The same repair when the base triangle's own apex is on the front (the centroid split
/// cannot help then: the quad would still touch the front at that apex). The shared edge j
/// (u, v) of t1 and its neighbour t2 (apex d) is split at its midpoint m, giving four
/// triangles; the half of t1 holding the base edge `base` is merged with the half of t2
/// across (u, m) or (m, v), so the quad's corners are the base edge, d and m, and the apex
/// of t1 stays inside the region, which is therefore not split there. The caller makes
/// sure d is not on the front. Checks as above.
OddSplitResult splitEdgeAndMerge(QuadMesh2d& mesh, VertexMetrics& metrics, int t1, int base, int j,
                                 double minQuality);

}  // namespace aniso::quad
