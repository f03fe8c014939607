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
  std::vector<Vec2> p;   ///< neighbour positions
  std::vector<Vec2> mp;  ///< S_Q · neighbour positions
};

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

/// Smallest η_M of the star with Q at mq (metric-space coordinates).
double starQuality(const Star& star, const Vec2& mq) {
  const std::size_t n = star.ring.size();
  double worst = 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    worst = std::min(worst, meanRatio(mq, star.mp[i], star.mp[j]));
  }
  return worst;
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

}  // namespace

SmoothingStats laplaceSmoothing(Triangulation2d& tri, const VertexMetricCache& metrics,
                                const SmoothingOptions& options) {
  if (metrics.size() != tri.numVertices())
    throw MeshingError("laplaceSmoothing: the metric cache does not match the triangulation");
  if (options.iterations < 0 || !(options.qualityFloor <= 1) || std::isnan(options.lowGradation))
    throw MeshingError("laplaceSmoothing: invalid options");
  SmoothingStats st;
  Star star;
  star.ring.reserve(32), star.p.reserve(32), star.mp.reserve(32);
  const std::uint32_t n = static_cast<std::uint32_t>(tri.numVertices());
  for (int sweep = 0; sweep < options.iterations; ++sweep) {
    for (std::uint32_t vi = 0; vi < n; ++vi) {
      const VertexId v(vi);
      if (!metrics.movable(v)) continue;
      ++st.visited;
      if (!gatherRing(tri, v, star.ring)) continue;
      const Mat2& s = metrics.transform(v);
      star.p.clear(), star.mp.clear();
      for (VertexId w : star.ring) {
        star.p.push_back(tri.point(w));
        star.mp.push_back(s * star.p.back());
      }
      const Vec2 q = tri.point(v);
      const bool metricVersion = metrics.gradation(v) > options.lowGradation;
      st.metricVersion += metricVersion;
      const Vec2 target = laplaceTarget(metrics, v, q, star, metricVersion, options.metricSize);
      if (!target.allFinite() || target == q) continue;
      const double required = std::min(starQuality(star, s * q), options.qualityFloor);
      bool accepted = false;
      for (const double step : {1.0, 0.5}) {
        const Vec2 p = q + step * (target - q);
        if (p == q) break;
        if (starQuality(star, s * p) < required || !starValid(star, p)) continue;
        moveVertex(tri, v, p);
        ++st.moved;
        st.halved += step < 1.0;
        accepted = true;
        break;
      }
      st.rejected += !accepted;
    }
  }
  return st;
}

}  // namespace aniso::improve
