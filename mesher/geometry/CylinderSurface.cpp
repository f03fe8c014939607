#include "mesher/geometry/CylinderSurface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesher/core/Error.h"
#include "mesher/geometry/PeriodicParameter.h"

namespace aniso {

CylinderSurface::CylinderSurface(const Frame& frame, double radius, double v0, double v1)
    : f_(frame), r_(radius), v0_(v0), v1_(v1) {
  if (!(radius > 0) || !std::isfinite(radius)) throw InputError("cylinder: radius must be positive");
  if (!(v0 < v1) || !std::isfinite(v1 - v0)) throw InputError("cylinder: empty or non-finite v bounds");
}

Vec3 CylinderSurface::point(const Vec2& uv) const {
  return f_.toWorld(r_ * std::cos(uv.x()), r_ * std::sin(uv.x()), uv.y());
}

SurfaceD1 CylinderSurface::d1(const Vec2& uv) const {
  const double c = std::cos(uv.x()), s = std::sin(uv.x());
  return {f_.toWorld(r_ * c, r_ * s, uv.y()), f_.direction(-r_ * s, r_ * c, 0), f_.z()};
}

SurfaceD2 CylinderSurface::d2(const Vec2& uv) const {
  const double c = std::cos(uv.x()), s = std::sin(uv.x());
  return {f_.toWorld(r_ * c, r_ * s, uv.y()), f_.direction(-r_ * s, r_ * c, 0), f_.z(),
          f_.direction(-r_ * c, -r_ * s, 0), Vec3::Zero(), Vec3::Zero()};
}

SurfaceDomain CylinderSurface::domain() const {
  SurfaceDomain d;
  d.u0 = 0; d.u1 = 2 * std::numbers::pi; d.v0 = v0_; d.v1 = v1_;
  d.uPeriodic = true; d.uPeriod = 2 * std::numbers::pi;
  return d;
}

std::unique_ptr<ParametricSurface> CylinderSurface::clone() const {
  return std::make_unique<CylinderSurface>(*this);
}

Vec2 CylinderSurface::project(const Vec3& x, const Vec2& start) const {
  const double su = std::isfinite(start.x()) ? start.x() : 0.0;
  if (!x.allFinite()) return Vec2(su, std::isfinite(start.y()) ? std::clamp(start.y(), v0_, v1_) : v0_);
  const Vec3 l = f_.toLocal(x);
  const double rho = std::hypot(l.x(), l.y());
  const double u = rho > 1e-15 * (r_ + l.norm())
                       ? nearestPeriodic(std::atan2(l.y(), l.x()), su, 2 * std::numbers::pi)
                       : su;
  return Vec2(u, std::clamp(l.z(), v0_, v1_));
}

}  // namespace aniso
