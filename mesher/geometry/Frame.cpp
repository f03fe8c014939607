#include "mesher/geometry/Frame.h"

#include <Eigen/Geometry>

#include <cmath>

#include "mesher/core/Error.h"

namespace aniso {

namespace {

Vec3 unitAxis(const Vec3& axis) {
  const double n = axis.norm();
  if (!(n > 0) || !std::isfinite(n)) throw InputError("frame: the axis direction is zero or not finite");
  return axis / n;
}

Vec3 leastAligned(const Vec3& z) {
  const Vec3 a = z.cwiseAbs();
  if (a.x() <= a.y() && a.x() <= a.z()) return Vec3::UnitX();
  return a.y() <= a.z() ? Vec3::UnitY() : Vec3::UnitZ();
}

}  // namespace

Frame::Frame(const Vec3& origin, const Vec3& axis, const Vec3& xDir) : o_(origin) {
  if (!origin.allFinite()) throw InputError("frame: the origin is not finite");
  z_ = unitAxis(axis);
  const Vec3 x = xDir - xDir.dot(z_) * z_;
  const double n = x.norm();
  if (!(n > 1e-12 * xDir.norm()) || !std::isfinite(n))
    throw InputError("frame: the x direction is zero or parallel to the axis");
  x_ = x / n;
  y_ = z_.cross(x_);
}

Frame::Frame(const Vec3& origin, const Vec3& axis) : Frame(origin, axis, leastAligned(unitAxis(axis))) {}

Vec3 Frame::toLocal(const Vec3& p) const {
  const Vec3 d = p - o_;
  return Vec3(d.dot(x_), d.dot(y_), d.dot(z_));
}

}  // namespace aniso
