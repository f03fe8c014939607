#pragma once
// Circle2d — c(t) = centre + r (cos t, sin t), counter-clockwise, natural range [0, 2π]
// (evaluation is periodic beyond it). A pcurve for holes and circular boundaries of
// analytic models; a loop walks it clockwise through a reversed EdgeUse.
#include "mesher/geometry/ParametricCurve2d.h"

namespace aniso {

class Circle2d final : public ParametricCurve2d {
 public:
  /// Throws InputError when radius <= 0 or a value is not finite.
  Circle2d(const Vec2& centre, double radius);

  Vec2 point(double t) const override;
  Curve2dD2 d2(double t) const override;
  double tMin() const override;
  double tMax() const override;
  std::unique_ptr<ParametricCurve2d> clone() const override;

 private:
  Vec2 c_;
  double r_;
};

}  // namespace aniso
