#pragma once
// CylinderSurface — p(u,v) = o + R (cos u·x + sin u·y) + v·z in a Frame (OCCT's
// Geom_CylindricalSurface convention). u ∈ [0, 2π] periodic, v ∈ [v0, v1].
// pu × pv points away from the axis.
#include "mesher/geometry/Frame.h"
#include "mesher/geometry/ParametricSurface.h"

namespace aniso {

class CylinderSurface final : public ParametricSurface {
 public:
  /// Throws InputError when radius <= 0 or the v bounds are empty or not finite.
  CylinderSurface(const Frame& frame, double radius, double v0, double v1);

  Vec3 point(const Vec2& uv) const override;
  SurfaceD1 d1(const Vec2& uv) const override;
  SurfaceD2 d2(const Vec2& uv) const override;
  SurfaceDomain domain() const override;
  std::unique_ptr<ParametricSurface> clone() const override;

  /// Exact: u from the angle (the period representative nearest start.u; start.u on the
  /// axis), v from the axial coordinate clamped to [v0, v1].
  Vec2 project(const Vec3& x, const Vec2& start) const override;

 private:
  Frame f_;
  double r_, v0_, v1_;
};

}  // namespace aniso
