#pragma once
// Postprocessing of the worst triangles (thesis sec. 4.6.4): "localizing and improving of
// any mesh element with very bad quality, which may have been left by previous operations".
//
// A triangle is bad when its η_M (metric: the blend of its vertices' cached metrics,
// VertexMetricCache::blend) is below badQuality; frozen triangles (touching a pole,
// VertexMetricCache) are left alone, and no flip touches one. Each round visits the triangle slots in
// index order; for a bad triangle it tries, in turn:
//   1. quality flips of its three edges: an edge is flipped (del2d::canFlip: convex,
//      never constrained) when the smaller η_M of the two new triangles exceeds the smaller
//      η_M of the two old ones (both measured in the quadrilateral's blended metric);
//   2. local optimisation of each movable vertex of the triangle: the vertex is moved
//      towards the point that makes the worst triangle of its star equilateral in the
//      vertex's metric (full, half, quarter step), accepted when every star triangle stays
//      counter-clockwise (exact orient2d) and the smallest η_M of the star increases;
//      repeated up to vertexIterations times while it improves.
// Rounds repeat until one changes nothing or `rounds` is reached. Every change is checked
// first; the result is valid whenever the input is.
#include "mesher/surface/improve/VertexMetricCache.h"

namespace aniso::improve {

struct PostprocessOptions {
  double badQuality = 0.6;
  int rounds = 3;
  int vertexIterations = 6;
};

struct PostprocessStats {
  long long badBefore = 0, badAfter = 0;  ///< bad live triangles at the start and the end
  long long flips = 0, moves = 0;
};

/// η_M of the live triangle t in the blend of its vertices' metrics.
double triangleQuality(const Triangulation2d& tri, const VertexMetricCache& metrics, TriId t);

/// Number of live triangles with triangleQuality < threshold.
long long countBadTriangles(const Triangulation2d& tri, const VertexMetricCache& metrics, double threshold);

/// Throws MeshingError when metrics.size() != tri.numVertices() or an option is invalid.
PostprocessStats postprocess(Triangulation2d& tri, const VertexMetricCache& metrics,
                             const PostprocessOptions& options = {});

}  // namespace aniso::improve
