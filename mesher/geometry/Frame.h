#pragma once
// Frame — a right-handed orthonormal frame (origin, x, y, z), the placement of the analytic
// surfaces and circles (OCCT's gp_Ax3/gp_Ax2 conventions: y = z × x).
#include "mesher/core/Types.h"

namespace aniso {

class Frame {
 public:
  /// The world frame at the origin.
  Frame() = default;
  /// z = axis normalised; x = xDir made orthogonal to z and normalised; y = z × x.
  /// Throws InputError when axis is zero/non-finite or xDir is (nearly) parallel to it.
  Frame(const Vec3& origin, const Vec3& axis, const Vec3& xDir);
  /// As above with x chosen automatically: the world axis least aligned with z, made
  /// orthogonal to it.
  Frame(const Vec3& origin, const Vec3& axis);

  const Vec3& origin() const { return o_; }
  const Vec3& x() const { return x_; }
  const Vec3& y() const { return y_; }
  const Vec3& z() const { return z_; }

  /// origin + a x + b y + c z
  Vec3 toWorld(double a, double b, double c) const { return o_ + a * x_ + b * y_ + c * z_; }
  /// World direction a x + b y + c z (no origin).
  Vec3 direction(double a, double b, double c) const { return a * x_ + b * y_ + c * z_; }
  /// Local coordinates (a, b, c) of a world point.
  Vec3 toLocal(const Vec3& p) const;

 private:
  Vec3 o_ = Vec3::Zero(), x_ = Vec3::UnitX(), y_ = Vec3::UnitY(), z_ = Vec3::UnitZ();
};

}  // namespace aniso
