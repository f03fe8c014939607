#include "mesher/surface/improve/FaceQuality.h"

#include <algorithm>
#include <span>
#include <utility>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/core/NodeBuckets.h"
#include "mesher/metric/MeanRatio.h"
#include "mesher/metric/MetricLength.h"
#include "mesher/metric/NonConformity.h"

namespace aniso {
namespace {

void addTriangle(FaceQuality& q, const ControlSpace2d& cs, const Vec2& a, const Vec2& b, const Vec2& c) {
  const SurfaceMetricAt m = cs.getMetric((a + b + c) / 3);
  q.eta.add(meanRatio(m.transformation(), a, b, c));
  try {
    q.ek.add(nonConformitySurface(m.sizing, m.parameterization, a, b, c));
  } catch (const MeshingError&) {
    ++q.degenerate;  // no simplex metric for a degenerate triangle
  }
}

void addEdge(FaceQuality& q, const ControlSpace2d& cs, const Vec2& a, const Vec2& b) {
  q.mu.add(metricLength<2>(cs.getMetric(0.5 * (a + b)).transformation(), a, b));
}

}  // namespace

FaceQuality faceQuality(const del2d::Triangulation2d& tri, const ControlSpace2d& cs) {
  FaceQuality q;
  for (std::uint32_t ti = 0; ti < tri.triangleSlots(); ++ti) {
    const del2d::TriId t(ti);
    if (!tri.isAlive(t)) continue;
    const Vec2 &a = tri.point(tri.vertex(t, 0)), &b = tri.point(tri.vertex(t, 1)), &c = tri.point(tri.vertex(t, 2));
    addTriangle(q, cs, a, b, c);
    for (int i = 0; i < 3; ++i) {
      const del2d::TriId u = tri.neighbour(t, i);
      if (u.valid() && u.index < ti) continue;  // counted from the other side
      addEdge(q, cs, tri.point(tri.vertex(t, del2d::kNext[i])), tri.point(tri.vertex(t, del2d::kPrev[i])));
    }
  }
  return q;
}

FaceQuality faceQuality(std::span<const Vec2> uv, std::span<const std::array<int, 3>> triangles,
                        const ControlSpace2d& cs) {
  FaceQuality q;
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || static_cast<std::size_t>(t[k]) >= uv.size())
        throw MeshingError("faceQuality: vertex index " + std::to_string(t[k]) + " out of range");
    addTriangle(q, cs, uv[t[0]], uv[t[1]], uv[t[2]]);
    for (int k = 0; k < 3; ++k) edges.emplace_back(std::minmax(t[k], t[(k + 1) % 3]));
  }
  // each edge once, in increasing (a, b) order (NodeBuckets.h)
  NodeBuckets<std::pair<int, int>> byNode = bucketByNode(std::span<const std::pair<int, int>>(edges), uv.size(),
                                                         [](const std::pair<int, int>& e) { return e.first; });
  for (std::size_t a = 0; a < byNode.nodes(); ++a) {
    const std::span<std::pair<int, int>> bucket = byNode.bucket(a);
    std::sort(bucket.begin(), bucket.end());
    for (auto it = bucket.begin(); it != bucket.end(); ++it)
      if (it == bucket.begin() || *it != *(it - 1)) addEdge(q, cs, uv[it->first], uv[it->second]);
  }
  return q;
}

}  // namespace aniso
