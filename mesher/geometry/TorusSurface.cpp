#include "mesher/geometry/TorusSurface.h"

#include <cmath>
#include <numbers>

#include "mesher/core/Error.h"
#include "mesher/geometry/PeriodicParameter.h"

namespace aniso {

TorusSurface::TorusSurface(const Frame& frame, double majorRadius, double minorRadius)
    : f_(frame), big_(majorRadius), small_(minorRadius) {
  if (!(minorRadius > 0) || !(majorRadius > minorRadius) || !std::isfinite(majorRadius))
    throw InputError("torus: radii must satisfy 0 < minor < major");
}

Vec3 TorusSurface::point(const Vec2& uv) const {
  const double w = big_ + small_ * std::cos(uv.y());
  return f_.toWorld(w * std::cos(uv.x()), w * std::sin(uv.x()), small_ * std::sin(uv.y()));
}

SurfaceD1 TorusSurface::d1(const Vec2& uv) const {
  const double cu = std::cos(uv.x()), su = std::sin(uv.x());
  const double cv = std::cos(uv.y()), sv = std::sin(uv.y());
  const double w = big_ + small_ * cv, r = small_;
  return {f_.toWorld(w * cu, w * su, r * sv), f_.direction(-w * su, w * cu, 0),
          f_.direction(-r * sv * cu, -r * sv * su, r * cv)};
}

SurfaceD2 TorusSurface::d2(const Vec2& uv) const {
  const double cu = std::cos(uv.x()), su = std::sin(uv.x());
  const double cv = std::cos(uv.y()), sv = std::sin(uv.y());
  const double w = big_ + small_ * cv, r = small_;
  return {f_.toWorld(w * cu, w * su, r * sv),
          f_.direction(-w * su, w * cu, 0),
          f_.direction(-r * sv * cu, -r * sv * su, r * cv),
          f_.direction(-w * cu, -w * su, 0),
          f_.direction(r * sv * su, -r * sv * cu, 0),
          f_.direction(-r * cv * cu, -r * cv * su, -r * sv)};
}

SurfaceDomain TorusSurface::domain() const {
  SurfaceDomain d;
  d.u0 = 0; d.u1 = 2 * std::numbers::pi; d.v0 = 0; d.v1 = 2 * std::numbers::pi;
  d.uPeriodic = d.vPeriodic = true;
  d.uPeriod = d.vPeriod = 2 * std::numbers::pi;
  return d;
}

std::unique_ptr<ParametricSurface> TorusSurface::clone() const {
  return std::make_unique<TorusSurface>(*this);
}

Vec2 TorusSurface::project(const Vec3& x, const Vec2& start) const {
  const double twoPi = 2 * std::numbers::pi;
  const Vec2 s(std::isfinite(start.x()) ? start.x() : 0.0, std::isfinite(start.y()) ? start.y() : 0.0);
  if (!x.allFinite()) return s;
  const Vec3 l = f_.toLocal(x);
  const double rho = std::hypot(l.x(), l.y());
  const double scale = big_ + l.norm();
  const double u = rho > 1e-15 * scale ? nearestPeriodic(std::atan2(l.y(), l.x()), s.x(), twoPi) : s.x();
  // In the meridian half-plane of u the tube centre is at (R, 0).
  const double radial = l.x() * std::cos(u) + l.y() * std::sin(u) - big_;
  const double v = std::hypot(radial, l.z()) > 1e-15 * scale
                       ? nearestPeriodic(std::atan2(l.z(), radial), s.y(), twoPi)
                       : s.y();
  return Vec2(u, v);
}

}  // namespace aniso
