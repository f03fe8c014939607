#pragma once
// ParametricCurve3d — a 3D curve c : C ⊂ R → R³ (fig. 6.3, eq. 2.43): the 3D geometry of a
// model edge. Thread safety as for ParametricSurface: use clone() per thread.
#include <functional>
#include <memory>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

struct Curve3dD2 {
  Vec3 p, d1, d2;
};

class ParametricCurve3d {
 public:
  virtual ~ParametricCurve3d() = default;

  virtual Vec3 point(double t) const = 0;
  virtual Curve3dD2 d2(double t) const = 0;
  virtual double tMin() const = 0;
  virtual double tMax() const = 0;
  virtual std::unique_ptr<ParametricCurve3d> clone() const = 0;

  /// Parameter of the nearest point within [t0, t1], starting from ts. Never throws.
  virtual double project(const Vec3& p, double ts, double t0, double t1) const;
  /// Euclidean arc length of [t0, t1].
  double length(double t0, double t1) const;
  /// Length in a 3D metric: integral of |M(c(t)) c'(t)| dt.
  double length(double t0, double t1, const std::function<Mat3(const Vec3&)>& transform) const;
  /// Polyline parameters of [t0, t1], chord deviation ≤ tol × chord length.
  std::vector<double> polyline(double t0, double t1, double tol = 1e-3) const;
  /// Curvature |c' × c''| / |c'|³ (eq. 2.45).
  double curvature(double t) const;
};

using Curve3dPtr = std::shared_ptr<const ParametricCurve3d>;

}  // namespace aniso
