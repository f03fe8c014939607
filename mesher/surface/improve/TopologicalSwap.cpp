#include "mesher/surface/improve/TopologicalSwap.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/surface/improve/GeometricSwap.h"

namespace aniso::improve {
namespace {

using del2d::kNext;
using del2d::kPrev;

/// Degree (number of edges) of every vertex, counting each edge once.
void vertexDegrees(const Triangulation2d& tri, std::vector<int>& degree) {
  degree.assign(tri.numVertices(), 0);
  for (std::uint32_t ti = 0; ti < tri.triangleSlots(); ++ti) {
    const TriId t(ti);
    if (!tri.isAlive(t)) continue;
    const std::uint32_t* tv = tri.triVertices(t);
    for (int i = 0; i < 3; ++i) {
      const TriId u = tri.neighbour(t, i);
      if (u.valid() && u.index < ti) continue;
      ++degree[tv[kNext[i]]];
      ++degree[tv[kPrev[i]]];
    }
  }
}

}  // namespace

TopologicalSwapStats topologicalSwap(Triangulation2d& tri, const VertexMetricCache& metrics,
                                     const TopologicalSwapOptions& options) {
  if (metrics.size() != tri.numVertices())
    throw MeshingError("topologicalSwap: the metric cache does not match the triangulation");
  TopologicalSwapStats st;
  std::vector<int> degree;
  vertexDegrees(tri, degree);
  const bool guard = std::isfinite(options.angleTolerance);
  const auto excess = [&](VertexId v) { return degree[v.index] - metrics.idealDegree(v); };
  for (std::uint32_t ti = 0; ti < tri.triangleSlots(); ++ti) {
    const TriId t(ti);
    if (!tri.isAlive(t)) continue;
    for (int i = 0; i < 3; ++i) {
      const TriId u = tri.neighbour(t, i);
      if (!u.valid() || u.index < ti || tri.isConstrained(t, i) || metrics.edgeFrozen(tri, t, i)) continue;
      ++st.checked;
      const int j = tri.neighbourIndex(u, t);
      if (j < 0) continue;
      // Quadrilateral a-b-d-c with the edge (b, c) (del2d FlipPlan naming).
      const VertexId q[4] = {tri.vertex(t, i), tri.vertex(t, kNext[i]), tri.vertex(t, kPrev[i]),
                             tri.vertex(u, j)};
      if (!(excess(q[1]) + excess(q[2]) > excess(q[0]) + excess(q[3]) + 2)) continue;
      bool graded = false;
      for (VertexId v : q) graded = graded || !(metrics.gradation(v) <= options.lowGradation);
      if (graded) continue;
      const del2d::FlipPlan plan = del2d::canFlip(tri, t, i);
      if (!plan.legal || !metrics.flipUpright(tri, plan)) continue;
      if (guard) {
        // After the flip the edge is (a, d); the angles opposite it are at b and c.
        const Mat2 m = metrics.blend(q, 4);
        const double sum = oppositeAngleSum(m, tri.point(q[1]), tri.point(q[0]), tri.point(q[3]), tri.point(q[2]));
        if (sum > std::numbers::pi + options.angleTolerance) continue;
      }
      del2d::flip(tri, plan);
      ++st.flipped;
      --degree[q[1].index], --degree[q[2].index];
      ++degree[q[0].index], ++degree[q[3].index];
    }
  }
  return st;
}

}  // namespace aniso::improve
