#pragma once
// Line3d — the straight segment c(t) = a + (t − t0)/(t1 − t0) (b − a): c(t0) = a, c(t1) = b
// (the 3D curve of a straight model edge, sec. 6.2.2). The natural range is [t0, t1].
#include "mesher/geometry/ParametricCurve3d.h"

namespace aniso {

class Line3d final : public ParametricCurve3d {
 public:
  /// Throws InputError when t0 == t1 or a value is not finite.
  Line3d(const Vec3& a, const Vec3& b, double t0 = 0, double t1 = 1);

  Vec3 point(double t) const override;
  Curve3dD2 d2(double t) const override;
  double tMin() const override { return t0_ < t1_ ? t0_ : t1_; }
  double tMax() const override { return t0_ < t1_ ? t1_ : t0_; }
  std::unique_ptr<ParametricCurve3d> clone() const override;

  /// Exact: the orthogonal foot, clamped to [t0, t1] (ts when a == b).
  double project(const Vec3& p, double ts, double t0, double t1) const override;

 private:
  Vec3 a_, dir_;
  double t0_, t1_;
};

}  // namespace aniso
