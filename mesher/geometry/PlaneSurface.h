#pragma once
// PlaneSurface — p(u,v) = origin + u·a + v·b on a given rectangle [u0,u1]×[v0,v1].
// The axis vectors need not be unit or orthogonal (a scaled axis gives a scaled
// parameterization, G = [a·a a·b; a·b b·b]), only independent. Analytic surface for models
// without CAD (sec. 6.2.1).
#include "mesher/geometry/ParametricSurface.h"

namespace aniso {

class PlaneSurface final : public ParametricSurface {
 public:
  /// Throws InputError when a, b are dependent or not finite, or the bounds are empty or
  /// not finite.
  PlaneSurface(const Vec3& origin, const Vec3& a, const Vec3& b, double u0, double u1, double v0,
               double v1);

  Vec3 point(const Vec2& uv) const override;
  SurfaceD1 d1(const Vec2& uv) const override;
  SurfaceD2 d2(const Vec2& uv) const override;
  SurfaceDomain domain() const override;
  std::unique_ptr<ParametricSurface> clone() const override;
  bool affine() const override { return true; }

  /// Constant unit normal a × b / |a × b|.
  Vec3 normal(const Vec2& uv) const override;
  /// Exact: the least-squares (u,v) of x, clamped to the rectangle.
  Vec2 project(const Vec3& x, const Vec2& start) const override;

 private:
  Vec3 o_, a_, b_;
  double u0_, u1_, v0_, v1_;
};

}  // namespace aniso
