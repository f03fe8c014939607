#include "mesher/geometry/SphereSurface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesher/core/Error.h"
#include "mesher/geometry/PeriodicParameter.h"

namespace aniso {

SphereSurface::SphereSurface(const Frame& frame, double radius) : f_(frame), r_(radius) {
  if (!(radius > 0) || !std::isfinite(radius)) throw InputError("sphere: radius must be positive");
}

Vec3 SphereSurface::point(const Vec2& uv) const {
  const double cv = std::cos(uv.y());
  return f_.toWorld(r_ * cv * std::cos(uv.x()), r_ * cv * std::sin(uv.x()), r_ * std::sin(uv.y()));
}

SurfaceD1 SphereSurface::d1(const Vec2& uv) const {
  const double cu = std::cos(uv.x()), su = std::sin(uv.x());
  const double cv = std::cos(uv.y()), sv = std::sin(uv.y());
  return {f_.toWorld(r_ * cv * cu, r_ * cv * su, r_ * sv),
          f_.direction(-r_ * cv * su, r_ * cv * cu, 0),
          f_.direction(-r_ * sv * cu, -r_ * sv * su, r_ * cv)};
}

SurfaceD2 SphereSurface::d2(const Vec2& uv) const {
  const double cu = std::cos(uv.x()), su = std::sin(uv.x());
  const double cv = std::cos(uv.y()), sv = std::sin(uv.y());
  return {f_.toWorld(r_ * cv * cu, r_ * cv * su, r_ * sv),
          f_.direction(-r_ * cv * su, r_ * cv * cu, 0),
          f_.direction(-r_ * sv * cu, -r_ * sv * su, r_ * cv),
          f_.direction(-r_ * cv * cu, -r_ * cv * su, 0),
          f_.direction(r_ * sv * su, -r_ * sv * cu, 0),
          f_.direction(-r_ * cv * cu, -r_ * cv * su, -r_ * sv)};
}

SurfaceDomain SphereSurface::domain() const {
  SurfaceDomain d;
  d.u0 = 0; d.u1 = 2 * std::numbers::pi;
  d.v0 = -0.5 * std::numbers::pi; d.v1 = 0.5 * std::numbers::pi;
  d.uPeriodic = true; d.uPeriod = 2 * std::numbers::pi;
  return d;
}

std::unique_ptr<ParametricSurface> SphereSurface::clone() const {
  return std::make_unique<SphereSurface>(*this);
}

Vec3 SphereSurface::normal(const Vec2& uv) const {
  const double cv = std::cos(uv.y());
  return f_.direction(cv * std::cos(uv.x()), cv * std::sin(uv.x()), std::sin(uv.y())).normalized();
}

Vec2 SphereSurface::project(const Vec3& x, const Vec2& start) const {
  const double halfPi = 0.5 * std::numbers::pi;
  const Vec2 s(std::isfinite(start.x()) ? start.x() : 0.0,
               std::isfinite(start.y()) ? std::clamp(start.y(), -halfPi, halfPi) : 0.0);
  if (!x.allFinite()) return s;
  const Vec3 l = f_.toLocal(x);
  const double rho = std::hypot(l.x(), l.y());
  if (!(l.norm() > 1e-15 * r_)) return s;  // the centre: every point is nearest
  const double u = rho > 1e-15 * l.norm()
                       ? nearestPeriodic(std::atan2(l.y(), l.x()), s.x(), 2 * std::numbers::pi)
                       : s.x();
  return Vec2(u, std::atan2(l.z(), rho));
}

}  // namespace aniso
