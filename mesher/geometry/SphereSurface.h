#pragma once
// SphereSurface — p(u,v) = o + R cos v (cos u·x + sin u·y) + R sin v·z in a Frame (OCCT's
// Geom_SphericalSurface convention): u longitude ∈ [0, 2π] periodic, v latitude ∈
// [−π/2, π/2], poles at v = ±π/2 (pu = 0 there). pu × pv points outwards, so with respect
// to normal() both principal curvatures are −1/R.
#include "mesher/geometry/Frame.h"
#include "mesher/geometry/ParametricSurface.h"

namespace aniso {

class SphereSurface final : public ParametricSurface {
 public:
  /// Throws InputError when radius <= 0 or not finite.
  SphereSurface(const Frame& frame, double radius);

  Vec3 point(const Vec2& uv) const override;
  SurfaceD1 d1(const Vec2& uv) const override;
  SurfaceD2 d2(const Vec2& uv) const override;
  SurfaceDomain domain() const override;
  std::unique_ptr<ParametricSurface> clone() const override;

  /// Exact: the radial normal direction (x − o)/|x − o|, also at the poles.
  Vec3 normal(const Vec2& uv) const override;
  /// Exact: longitude (representative nearest start.u; start.u on the axis) and latitude.
  Vec2 project(const Vec3& x, const Vec2& start) const override;

 private:
  Frame f_;
  double r_;
};

}  // namespace aniso
