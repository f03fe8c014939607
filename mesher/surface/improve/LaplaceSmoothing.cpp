#include "mesher/surface/improve/LaplaceSmoothing.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/metric/MeanRatio.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::improve {
namespace {

/// Scratch of one call: the star of the current vertex.
struct Star {
  std::vector<VertexId> ring;
  std::vector<TriId> tris;  ///< star triangle k = (Q, P_k, P_k+1)
  std::vector<Vec2> p;  ///< neighbour positions
  std::vector<Mat2> m;  ///< metric of star triangle k = (Q, P_k, P_k+1): blend of its vertices
};

/// Worst and mean η_M of the star with Q at q.
struct StarQuality {
  double worst = 1.0, mean = 0.0;
};

StarQuality starQuality(const Star& star, const Vec2& q) {
  const std::size_t n = star.ring.size();
  StarQuality r;
  for (std::size_t i = 0; i < n; ++i) {
    const double e = meanRatio(star.m[i], q, star.p[i], star.p[i + 1 == n ? 0 : i + 1]);
    r.worst = std::min(r.worst, e);
    r.mean += e;
  }
  r.mean /= static_cast<double>(n);
  return r;
}

/// Eq. 4.2 or 4.3 (see the header).
Vec2 laplaceTarget(const VertexMetricCache& metrics, VertexId q, const Vec2& pq, const Star& star,
                   bool metricVersion, bool metricSize) {
  const std::size_t n = star.ring.size();
  Vec2 sum = Vec2::Zero();
  if (!metricVersion) {
    for (std::size_t i = 0; i < n; ++i) sum += star.p[i];
    return sum / static_cast<double>(n);
  }
  const Mat2& invQ = metrics.inverse(q);
  const double detQ = metrics.transform(q).determinant();
  for (std::size_t i = 0; i < n; ++i) {
    Mat2 mid = (0.5 * (invQ + metrics.inverse(star.ring[i]))).inverse();  // eq. 2.18 at the middle
    if (!metricSize) mid *= std::sqrt(detQ / mid.determinant());          // Q's size, the mid shape
    sum += mid * (star.p[i] - pq);
  }
  return pq + invQ * (sum / static_cast<double>(n));
}

/// Every star triangle counter-clockwise with Q at p (exact).
bool starValid(const Star& star, const Vec2& p) {
  const std::size_t n = star.ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    if (!(predicates::orient2d(p.data(), star.p[i].data(), star.p[j].data()) > 0)) return false;
  }
  return true;
}

/// The blended metric of each triangle (VertexMetricCache::blend of its corners), computed
/// at its first use: smoothing moves vertices only, so neither the triangles nor the
/// vertices' metrics change during laplaceSmoothing.
class TriangleMetrics {
 public:
  TriangleMetrics(const Triangulation2d& tri, const VertexMetricCache& metrics)
      : tri_(tri), metrics_(metrics), m_(tri.triangleSlots()), have_(tri.triangleSlots(), 0) {}
  const Mat2& operator[](TriId t) {
    if (!have_[t.index]) {
      const std::uint32_t* tv = tri_.triVertices(t);
      const VertexId corners[3] = {VertexId(tv[0]), VertexId(tv[1]), VertexId(tv[2])};
      m_[t.index] = metrics_.blend(corners, 3);
      have_[t.index] = 1;
    }
    return m_[t.index];
  }

 private:
  const Triangulation2d& tri_;
  const VertexMetricCache& metrics_;
  std::vector<Mat2> m_;
  std::vector<std::uint8_t> have_;
};

/// One vertex: gather its star, compute the target, check, then move. Updates st.
void smoothVertex(Triangulation2d& tri, const VertexMetricCache& metrics, TriangleMetrics& triangleMetrics,
                  VertexId v, const SmoothingOptions& options, Star& star, SmoothingStats& st) {
  if (!gatherRing(tri, v, star.ring, star.tris)) return;
  star.p.clear(), star.m.clear();
  const std::size_t degree = star.ring.size();
  for (std::size_t k = 0; k < degree; ++k) {
    star.p.push_back(tri.point(star.ring[k]));
    star.m.push_back(triangleMetrics[star.tris[k]]);
  }
  const Vec2 q = tri.point(v);
  const bool metricVersion = metrics.gradation(v) > options.lowGradation;
  st.metricVersion += metricVersion;
  const Vec2 target = laplaceTarget(metrics, v, q, star, metricVersion, options.metricSize);
  if (!target.allFinite() || target == q) return;
  const StarQuality before = starQuality(star, q);
  const bool poor = before.worst < options.qualityFloor;
  for (const double step : {1.0, 0.5}) {
    const Vec2 p = q + step * (target - q);
    if (p == q) break;
    const StarQuality after = starQuality(star, p);
    const bool better = poor ? after.worst > before.worst
                             : after.worst >= options.qualityFloor && after.mean >= before.mean;
    if (!better || !starValid(star, p) || !metrics.fanUpright(tri, p, star.ring)) continue;
    moveVertex(tri, v, p);
    ++st.moved;
    st.halved += step < 1.0;
    return;
  }
  ++st.rejected;
}

}  // namespace

SmoothingStats laplaceSmoothing(Triangulation2d& tri, const VertexMetricCache& metrics,
                                const SmoothingOptions& options) {
  if (metrics.size() != tri.numVertices())
    throw MeshingError("laplaceSmoothing: the metric cache does not match the triangulation");
  if (options.iterations < 0 || !(options.qualityFloor <= 1) || std::isnan(options.lowGradation))
    throw MeshingError("laplaceSmoothing: invalid options");
  SmoothingStats st;
  Star star;
  star.ring.reserve(32), star.tris.reserve(32), star.p.reserve(32), star.m.reserve(32);
  TriangleMetrics triangleMetrics(tri, metrics);
  const std::uint32_t n = static_cast<std::uint32_t>(tri.numVertices());
  for (int sweep = 0; sweep < options.iterations; ++sweep)
    for (std::uint32_t v = 0; v < n; ++v)
      if (metrics.movable(VertexId(v))) {
        ++st.visited;
        smoothVertex(tri, metrics, triangleMetrics, VertexId(v), options, star, st);
      }
  return st;
}

}  // namespace aniso::improve
