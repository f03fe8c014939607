#include "mesher/geometry/Line3d.h"

#include <algorithm>
#include <cmath>

#include "mesher/core/Error.h"

namespace aniso {

Line3d::Line3d(const Vec3& a, const Vec3& b, double t0, double t1) : a_(a), t0_(t0), t1_(t1) {
  if (!a.allFinite() || !b.allFinite() || !std::isfinite(t0) || !std::isfinite(t1) || t0 == t1)
    throw InputError("line3d: non-finite points or an empty parameter range");
  dir_ = (b - a) / (t1 - t0);
}

Vec3 Line3d::point(double t) const { return a_ + (t - t0_) * dir_; }

Curve3dD2 Line3d::d2(double t) const { return {point(t), dir_, Vec3::Zero()}; }

std::unique_ptr<ParametricCurve3d> Line3d::clone() const { return std::make_unique<Line3d>(*this); }

double Line3d::project(const Vec3& p, double ts, double t0, double t1) const {
  const double lo = std::min(t0, t1), hi = std::max(t0, t1);
  const double l2 = dir_.squaredNorm();
  if (!(l2 > 0) || !p.allFinite()) return std::clamp(std::isfinite(ts) ? ts : lo, lo, hi);
  return std::clamp(t0_ + (p - a_).dot(dir_) / l2, lo, hi);
}

}  // namespace aniso
