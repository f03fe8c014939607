#include "mesher/geometry/Circle3d.h"

#include <cmath>
#include <numbers>

#include "mesher/core/Error.h"

namespace aniso {

Circle3d::Circle3d(const Frame& frame, double radius) : f_(frame), r_(radius) {
  if (!(radius > 0) || !std::isfinite(radius)) throw InputError("circle3d: radius must be positive");
}

Vec3 Circle3d::point(double t) const { return f_.toWorld(r_ * std::cos(t), r_ * std::sin(t), 0); }

Curve3dD2 Circle3d::d2(double t) const {
  const double c = std::cos(t), s = std::sin(t);
  return {f_.toWorld(r_ * c, r_ * s, 0), f_.direction(-r_ * s, r_ * c, 0), f_.direction(-r_ * c, -r_ * s, 0)};
}

double Circle3d::tMin() const { return 0; }
double Circle3d::tMax() const { return 2 * std::numbers::pi; }

std::unique_ptr<ParametricCurve3d> Circle3d::clone() const { return std::make_unique<Circle3d>(*this); }

}  // namespace aniso
