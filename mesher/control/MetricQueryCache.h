#pragma once
// MetricQueryCache2d / 3d — the "proximity check for control space calls" of sec. 3.2.4
// item 3: a caller-owned cache of the last query (point and metric). A new query within
// `maxMetricDistance` of the cached point, measured in the cached metric (d_M = |M Δx|
// with M = M_s M_p in 2D), reuses the cached metric without touching the control space.
//
// The cache belongs to the caller (one per thread or per meshing front), never to the
// control space, so control spaces stay free of mutable state. It remembers which control
// space answered and its revision(), so a query to another space or after a modification
// is never served from the cache. (Immutable spaces all report revision 0: clear() the
// cache when the control space it was used with is destroyed and replaced.)
// Choice of maxMetricDistance: the metric is then taken constant over that fraction of
// an element; e.g. 0.05 changes lengths by well under 5 % for gradations γ_M ≤ 4.
// Not thread-safe (one cache per thread); header-only.
#include <cstdint>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/control/ControlSpace3d.h"
#include "mesher/core/Error.h"

namespace aniso {

namespace detail {
inline double checkedProximity(double d) {
  if (!(d >= 0 && d < 1e300)) throw InputError("metric query cache: maximum metric distance must be finite and >= 0");
  return d;
}
}  // namespace detail

class MetricQueryCache2d {
 public:
  explicit MetricQueryCache2d(double maxMetricDistance) : maxDistance_(detail::checkedProximity(maxMetricDistance)) {}

  SurfaceMetricAt get(const ControlSpace2d& cs, const Vec2& uv) {
    if (space_ == &cs && revision_ == cs.revision() && (m_ * (uv - point_)).norm() <= maxDistance_) {
      ++hits_;
      return metric_;
    }
    ++misses_;
    metric_ = cs.getMetric(uv);
    m_ = metric_.transformation();
    point_ = uv;
    space_ = &cs;
    revision_ = cs.revision();
    return metric_;
  }
  void clear() { space_ = nullptr; }
  std::uint64_t hits() const { return hits_; }
  std::uint64_t misses() const { return misses_; }

 private:
  double maxDistance_;
  const ControlSpace2d* space_ = nullptr;
  std::uint64_t revision_ = 0, hits_ = 0, misses_ = 0;
  Vec2 point_ = Vec2::Zero();
  SurfaceMetricAt metric_;
  Mat2 m_ = Mat2::Identity();
};

class MetricQueryCache3d {
 public:
  explicit MetricQueryCache3d(double maxMetricDistance) : maxDistance_(detail::checkedProximity(maxMetricDistance)) {}

  Metric3d get(const ControlSpace3d& cs, const Vec3& x) {
    if (space_ == &cs && revision_ == cs.revision() && metric_.distance(point_, x) <= maxDistance_) {
      ++hits_;
      return metric_;
    }
    ++misses_;
    metric_ = cs.getMetric(x);
    point_ = x;
    space_ = &cs;
    revision_ = cs.revision();
    return metric_;
  }
  void clear() { space_ = nullptr; }
  std::uint64_t hits() const { return hits_; }
  std::uint64_t misses() const { return misses_; }

 private:
  double maxDistance_;
  const ControlSpace3d* space_ = nullptr;
  std::uint64_t revision_ = 0, hits_ = 0, misses_ = 0;
  Vec3 point_ = Vec3::Zero();
  Metric3d metric_;
};

}  // namespace aniso
