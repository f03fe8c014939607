#pragma once
// Circle3d — c(t) = o + r (cos t·x + sin t·y) in a Frame (OCCT's Geom_Circle convention),
// natural range [0, 2π] (evaluation is periodic beyond it).
#include "mesher/geometry/Frame.h"
#include "mesher/geometry/ParametricCurve3d.h"

namespace aniso {

class Circle3d final : public ParametricCurve3d {
 public:
  /// Throws InputError when radius <= 0 or not finite.
  Circle3d(const Frame& frame, double radius);

  Vec3 point(double t) const override;
  Curve3dD2 d2(double t) const override;
  double tMin() const override;
  double tMax() const override;
  std::unique_ptr<ParametricCurve3d> clone() const override;

 private:
  Frame f_;
  double r_;
};

}  // namespace aniso
