#pragma once
// MetricContext2d / MetricContext3d — the "current metric" of a meshing operation and the
// vertex cache of metric-space coordinates (sec. 3.2.4 items 2–3, sec. 6.4.1).
//
// A context holds the transformation tensor set as locally constant (2D: M = M_s M_p with
// its components, eq. 2.9; 3D: M = M_s, eq. 2.16) and a counter. Every set…() changes the
// counter; a vertex keeps a MetricCoords (its coordinates in metric space plus the counter
// they were computed for) and metricCoordinates() returns them when still valid, else
// recomputes and stores them. A vertex that moves must invalidate() its cache.
//
// Counter values are unique across all contexts of the process (each context draws blocks
// of values from one atomic source), so a cache filled through one context is never taken
// as valid by another — also with one context per thread. Copies of a context share the
// counter value (same metric, so caches stay valid) but draw new values after a change.
// Counter value 0 is never used: a fresh MetricCoords is always invalid.
//
// A context also remembers the point its metric was set for, if given, for the proximity
// check of sec. 3.2.4 item 3 (covers()).
// Not thread-safe: one context per thread. No allocation; all accessors inline.
#include <cstdint>

#include "mesher/metric/Metric.h"

namespace aniso {

namespace detail {
/// First value of a fresh block of kMetricCounterBlock unique counter values (thread-safe).
std::uint64_t reserveMetricCounterBlock();
inline constexpr std::uint64_t kMetricCounterBlock = std::uint64_t(1) << 20;

/// Unique counter values drawn block by block; copies start a new block when they change.
class MetricCounter {
 public:
  MetricCounter() = default;
  MetricCounter(const MetricCounter& o) : value_(o.value_) {}
  MetricCounter& operator=(const MetricCounter& o) {
    value_ = o.value_;
    next_ = end_ = 0;
    return *this;
  }
  std::uint64_t value() const { return value_; }
  void advance() {
    if (next_ == end_) {
      next_ = reserveMetricCounterBlock();
      end_ = next_ + kMetricCounterBlock;
    }
    value_ = next_++;
  }

 private:
  std::uint64_t value_ = 0, next_ = 0, end_ = 0;
};
}  // namespace detail

/// Cached metric-space coordinates of a 2D (parametric) vertex.
struct MetricCoords2d {
  Vec2 p = Vec2::Zero();
  std::uint64_t counter = 0;  ///< 0: never computed
  void invalidate() { counter = 0; }
};

/// Cached metric-space coordinates of a 3D vertex.
struct MetricCoords3d {
  Vec3 p = Vec3::Zero();
  std::uint64_t counter = 0;
  void invalidate() { counter = 0; }
};

class MetricContext2d {
 public:
  /// Starts with M_s = M_p = I (planar, unit lengths) and a valid counter value.
  MetricContext2d() { counter_.advance(); }

  /// Surface metric: M = M_s M_p (eq. 2.9). Always advances the counter.
  void set(const Metric2d& sizing, const Mat2& parameterization) {
    sizing_ = sizing;
    mp_ = parameterization;
    m_ = sizing.matrix() * parameterization;
    hasAnchor_ = false;
    counter_.advance();
  }
  /// Planar metric (M_p = I).
  void set(const Metric2d& sizing) { set(sizing, Mat2::Identity()); }
  /// As set(), remembering the point `at` the metric was computed for.
  void setAt(const Vec2& at, const Metric2d& sizing, const Mat2& parameterization) {
    set(sizing, parameterization);
    anchor_ = at;
    hasAnchor_ = true;
  }

  std::uint64_t counter() const { return counter_.value(); }
  /// M = M_s M_p.
  const Mat2& transformation() const { return m_; }
  const Metric2d& sizing() const { return sizing_; }
  const Mat2& parameterization() const { return mp_; }

  /// P^M = M P (eq. 2.10).
  Vec2 toMetricSpace(const Vec2& p) const { return m_ * p; }
  /// P^R = M_p P (eq. 2.12).
  Vec2 toRealSpace(const Vec2& p) const { return mp_ * p; }
  /// d_M (eq. 2.11) and d_R (eq. 2.13) with the current metric.
  double metricDistance(const Vec2& a, const Vec2& b) const { return (m_ * (b - a)).norm(); }
  double realDistance(const Vec2& a, const Vec2& b) const { return (mp_ * (b - a)).norm(); }

  /// True when the metric was set with setAt() and p is within `maxMetricDistance` of that
  /// point in the current metric: the metric may be reused for p (sec. 3.2.4 item 3).
  bool covers(const Vec2& p, double maxMetricDistance) const {
    return hasAnchor_ && metricDistance(anchor_, p) <= maxMetricDistance;
  }

 private:
  Metric2d sizing_;
  Mat2 mp_ = Mat2::Identity();
  Mat2 m_ = Mat2::Identity();
  Vec2 anchor_ = Vec2::Zero();
  bool hasAnchor_ = false;
  detail::MetricCounter counter_;
};

class MetricContext3d {
 public:
  MetricContext3d() { counter_.advance(); }

  /// M = M_s (eq. 2.16). Always advances the counter.
  void set(const Metric3d& m) {
    m_ = m;
    hasAnchor_ = false;
    counter_.advance();
  }
  void setAt(const Vec3& at, const Metric3d& m) {
    set(m);
    anchor_ = at;
    hasAnchor_ = true;
  }

  std::uint64_t counter() const { return counter_.value(); }
  const Metric3d& transformation() const { return m_; }

  /// P^M = M P (eq. 2.17).
  Vec3 toMetricSpace(const Vec3& p) const { return m_.apply(p); }
  double metricDistance(const Vec3& a, const Vec3& b) const { return m_.distance(a, b); }
  bool covers(const Vec3& p, double maxMetricDistance) const {
    return hasAnchor_ && metricDistance(anchor_, p) <= maxMetricDistance;
  }

 private:
  Metric3d m_;
  Vec3 anchor_ = Vec3::Zero();
  bool hasAnchor_ = false;
  detail::MetricCounter counter_;
};

/// The metric-space coordinates of x for the context's current metric: the cached ones
/// when cache.counter matches, else M x, stored in the cache (getMetricSpaceCoordinates).
inline const Vec2& metricCoordinates(const MetricContext2d& mc, const Vec2& x, MetricCoords2d& cache) {
  if (cache.counter != mc.counter()) {
    cache.p = mc.toMetricSpace(x);
    cache.counter = mc.counter();
  }
  return cache.p;
}

inline const Vec3& metricCoordinates(const MetricContext3d& mc, const Vec3& x, MetricCoords3d& cache) {
  if (cache.counter != mc.counter()) {
    cache.p = mc.toMetricSpace(x);
    cache.counter = mc.counter();
  }
  return cache.p;
}

}  // namespace aniso
