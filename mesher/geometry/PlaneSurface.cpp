#include "mesher/geometry/PlaneSurface.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

#include "mesher/core/Error.h"

namespace aniso {

PlaneSurface::PlaneSurface(const Vec3& origin, const Vec3& a, const Vec3& b, double u0, double u1,
                           double v0, double v1)
    : o_(origin), a_(a), b_(b), u0_(u0), u1_(u1), v0_(v0), v1_(v1) {
  if (!origin.allFinite() || !a.allFinite() || !b.allFinite())
    throw InputError("plane: origin or axis vectors not finite");
  if (!(a.cross(b).norm() > 1e-12 * a.norm() * b.norm()) || a.norm() == 0 || b.norm() == 0)
    throw InputError("plane: the axis vectors are zero or parallel");
  if (!(u0 < u1) || !(v0 < v1) || !std::isfinite(u1 - u0) || !std::isfinite(v1 - v0))
    throw InputError("plane: empty or non-finite parameter bounds");
}

Vec3 PlaneSurface::point(const Vec2& uv) const { return o_ + uv.x() * a_ + uv.y() * b_; }

SurfaceD1 PlaneSurface::d1(const Vec2& uv) const { return {point(uv), a_, b_}; }

SurfaceD2 PlaneSurface::d2(const Vec2& uv) const {
  return {point(uv), a_, b_, Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
}

SurfaceDomain PlaneSurface::domain() const {
  SurfaceDomain d;
  d.u0 = u0_; d.u1 = u1_; d.v0 = v0_; d.v1 = v1_;
  return d;
}

std::unique_ptr<ParametricSurface> PlaneSurface::clone() const {
  return std::make_unique<PlaneSurface>(*this);
}

Vec3 PlaneSurface::normal(const Vec2&) const { return a_.cross(b_).normalized(); }

Vec2 PlaneSurface::project(const Vec3& x, const Vec2& start) const {
  if (!x.allFinite()) return start;
  Mat2 g;
  g << a_.dot(a_), a_.dot(b_), a_.dot(b_), b_.dot(b_);
  const Vec3 d = x - o_;
  const Vec2 uv = g.inverse() * Vec2(a_.dot(d), b_.dot(d));
  return Vec2(std::clamp(uv.x(), u0_, u1_), std::clamp(uv.y(), v0_, v1_));
}

}  // namespace aniso
