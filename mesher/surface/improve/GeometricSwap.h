#pragma once
// Geometric edge swap (thesis sec. 4.6.3): the Delaunay inner-angles criterion (sec.
// 4.2.2; for Fig. 4.9(b) cos α + cos β ≥ 0, i.e. the two angles opposite an edge sum to at
// most π) evaluated in metric space; an edge that does not satisfy it is flipped.
//
// The metric of each quadrilateral is computed independently (sec. 4.2.2, last paragraph:
// the "more local variation" used during mesh improvement): the blend of the cached
// metrics of its four vertices (VertexMetricCache::blend, the same for both diagonals,
// so the criterion cannot prefer both). Edges of frozen triangles (touching a pole,
// VertexMetricCache) are not swapped. Check, then change: the criterion first, then
// del2d::canFlip (never a constrained edge, only strictly convex quadrilaterals), then
// del2d::flip.
//
// Applied "iteratively for all edges in mesh (using a marking system to avoid unnecessary
// calculations) until the condition is satisfied throughout the mesh": sweeps over the
// triangle slots in index order check the edges of the triangles marked dirty (all at the
// start; a flip marks the two triangles and their neighbours) until a sweep flips nothing.
// Since a variable metric may make flips cycle, the number of flips is capped
// (maxFlipsPerTriangle × live triangles), as the thesis caps swaps per point (Table 4.1).
#include <cstddef>

#include "mesher/surface/improve/VertexMetricCache.h"

namespace aniso::improve {

struct GeometricSwapOptions {
  /// Flip when the angle sum exceeds π + angleTolerance (radians, ≥ 0). With 0 the test is
  /// del2d::violatesInnerAngles itself (exact agreement with the kernel's criterion).
  double angleTolerance = 0;
  double maxFlipsPerTriangle = 8;
};

struct GeometricSwapStats {
  long long checked = 0, flipped = 0;
  int sweeps = 0;
  bool limitReached = false;
};

/// The angles at a and d opposite the edge (b, c) of the quadrilateral a-b-d-c (del2d
/// FlipPlan naming) in the metric space of m, summed (radians, in [0, 2π)).
double oppositeAngleSum(const Mat2& m, const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

/// Whether edge i of the live triangle t violates the criterion in the metric of its
/// quadrilateral (false on the border and for constrained edges).
bool violatesSwapCriterion(const Triangulation2d& tri, const VertexMetricCache& metrics, TriId t, int i,
                           double angleTolerance);

/// Throws MeshingError when metrics.size() != tri.numVertices() or an option is invalid.
GeometricSwapStats geometricSwap(Triangulation2d& tri, const VertexMetricCache& metrics,
                                 const GeometricSwapOptions& options = {});

}  // namespace aniso::improve
