#include "mesher/geometry/Circle2d.h"

#include <cmath>
#include <numbers>

#include "mesher/core/Error.h"

namespace aniso {

Circle2d::Circle2d(const Vec2& centre, double radius) : c_(centre), r_(radius) {
  if (!centre.allFinite() || !(radius > 0) || !std::isfinite(radius))
    throw InputError("circle2d: radius must be positive and values finite");
}

Vec2 Circle2d::point(double t) const { return c_ + r_ * Vec2(std::cos(t), std::sin(t)); }

Curve2dD2 Circle2d::d2(double t) const {
  const double c = std::cos(t), s = std::sin(t);
  return {c_ + r_ * Vec2(c, s), r_ * Vec2(-s, c), r_ * Vec2(-c, -s)};
}

double Circle2d::tMin() const { return 0; }
double Circle2d::tMax() const { return 2 * std::numbers::pi; }

std::unique_ptr<ParametricCurve2d> Circle2d::clone() const { return std::make_unique<Circle2d>(*this); }

}  // namespace aniso
