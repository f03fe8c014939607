#pragma once
// Moving parametric points of a periodic surface by whole periods (SurfaceDomain uPeriod,
// vPeriod): into a control space's rectangle before a metric query, and next to a
// neighbour when chaining the pcurves of a loop (OCCT may store a pcurve one period away
// from the previous one).
#include <cmath>

#include "mesher/core/Types.h"
#include "mesher/geometry/ParametricSurface.h"
#include "mesher/geometry/PeriodicParameter.h"

namespace aniso::contour {

class PeriodicUv {
 public:
  PeriodicUv() = default;
  /// `bounds` may be empty (then intoBounds() is the identity).
  PeriodicUv(const SurfaceDomain& domain, const Box2& bounds) : bounds_(bounds) {
    if (domain.uPeriodic && domain.uPeriod > 0 && std::isfinite(domain.uPeriod)) period_.x() = domain.uPeriod;
    if (domain.vPeriodic && domain.vPeriod > 0 && std::isfinite(domain.vPeriod)) period_.y() = domain.vPeriod;
  }

  /// The periods, 0 in a direction that is not periodic.
  const Vec2& period() const { return period_; }

  /// uv moved by whole periods into the rectangle in every periodic direction where it is
  /// outside; when no representative falls inside, the one nearest to the rectangle.
  Vec2 intoBounds(const Vec2& uv) const {
    if (bounds_.empty()) return uv;
    Vec2 out = uv;
    for (int i = 0; i < 2; ++i) {
      const double p = period_[i], lo = bounds_.lo[i], hi = bounds_.hi[i], x = uv[i];
      if (!(p > 0) || !std::isfinite(x) || (x >= lo && x <= hi)) continue;
      const double above = x + p * std::ceil((lo - x) / p);  // first representative >= lo
      out[i] = (above <= hi || above - hi <= lo - (above - p)) ? above : above - p;
    }
    return out;
  }

  /// The shift by whole periods that moves `from` nearest to `to` (0 in non-periodic
  /// directions).
  Vec2 shiftToward(const Vec2& from, const Vec2& to) const {
    Vec2 s(0, 0);
    for (int i = 0; i < 2; ++i)
      if (period_[i] > 0) s[i] = nearestPeriodic(from[i], to[i], period_[i]) - from[i];
    return s;
  }

 private:
  Box2 bounds_;
  Vec2 period_{0, 0};
};

}  // namespace aniso::contour
