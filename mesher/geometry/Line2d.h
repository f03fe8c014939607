#pragma once
// Line2d — the straight segment c(t) = a + (t − t0)/(t1 − t0) (b − a) in the parametric
// plane: c(t0) = a, c(t1) = b (a pcurve for analytic models, sec. 6.2.2). Evaluation
// extrapolates outside [t0, t1], which is also the natural range.
#include "mesher/geometry/ParametricCurve2d.h"

namespace aniso {

class Line2d final : public ParametricCurve2d {
 public:
  /// Throws InputError when t0 == t1 or a value is not finite (a == b is allowed: a
  /// degenerate pcurve collapses to a point).
  Line2d(const Vec2& a, const Vec2& b, double t0 = 0, double t1 = 1);

  Vec2 point(double t) const override;
  Curve2dD2 d2(double t) const override;
  double tMin() const override { return t0_ < t1_ ? t0_ : t1_; }
  double tMax() const override { return t0_ < t1_ ? t1_ : t0_; }
  std::unique_ptr<ParametricCurve2d> clone() const override;

  /// Exact: the orthogonal foot, clamped to [t0, t1] (ts when a == b).
  double project(const Vec2& p, double ts, double t0, double t1) const override;

 private:
  Vec2 a_, dir_;  ///< dir = dc/dt
  double t0_, t1_;
};

}  // namespace aniso
