#pragma once
// TorusSurface — p(u,v) = o + (R + r cos v)(cos u·x + sin u·y) + r sin v·z in a Frame
// (OCCT's Geom_ToroidalSurface convention): u around the axis, v around the tube, both
// in [0, 2π] and periodic; v = 0 is the outer equator, v = π the inner one. pu × pv points
// out of the tube, so with respect to normal() the principal curvatures are
// −1/r and −cos v/(R + r cos v): −1/r, −1/(R+r) on the outer equator and −1/r, +1/(R−r)
// on the inner one.
#include "mesher/geometry/Frame.h"
#include "mesher/geometry/ParametricSurface.h"

namespace aniso {

class TorusSurface final : public ParametricSurface {
 public:
  /// Throws InputError unless 0 < minorRadius < majorRadius (finite).
  TorusSurface(const Frame& frame, double majorRadius, double minorRadius);

  Vec3 point(const Vec2& uv) const override;
  SurfaceD1 d1(const Vec2& uv) const override;
  SurfaceD2 d2(const Vec2& uv) const override;
  SurfaceDomain domain() const override;
  std::unique_ptr<ParametricSurface> clone() const override;

  /// Exact: u from the angle around the axis, v from the angle around the tube centre
  /// circle, each the period representative nearest to start (start's value where the
  /// angle is undefined: on the axis, on the centre circle).
  Vec2 project(const Vec3& x, const Vec2& start) const override;

 private:
  Frame f_;
  double big_, small_;
};

}  // namespace aniso
