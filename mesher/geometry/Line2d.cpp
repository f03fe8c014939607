#include "mesher/geometry/Line2d.h"

#include <algorithm>
#include <cmath>

#include "mesher/core/Error.h"

namespace aniso {

Line2d::Line2d(const Vec2& a, const Vec2& b, double t0, double t1) : a_(a), t0_(t0), t1_(t1) {
  if (!a.allFinite() || !b.allFinite() || !std::isfinite(t0) || !std::isfinite(t1) || t0 == t1)
    throw InputError("line2d: non-finite points or an empty parameter range");
  dir_ = (b - a) / (t1 - t0);
}

Vec2 Line2d::point(double t) const { return a_ + (t - t0_) * dir_; }

Curve2dD2 Line2d::d2(double t) const { return {point(t), dir_, Vec2::Zero()}; }

std::unique_ptr<ParametricCurve2d> Line2d::clone() const { return std::make_unique<Line2d>(*this); }

double Line2d::project(const Vec2& p, double ts, double t0, double t1) const {
  const double lo = std::min(t0, t1), hi = std::max(t0, t1);
  const double l2 = dir_.squaredNorm();
  if (!(l2 > 0) || !p.allFinite()) return std::clamp(std::isfinite(ts) ? ts : lo, lo, hi);
  return std::clamp(t0_ + (p - a_).dot(dir_) / l2, lo, hi);
}

}  // namespace aniso
