// General methods of ParametricCurve3d (thesis sec. 2.4.3, 6.2.2).
#include "mesher/geometry/ParametricCurve3d.h"

#include <Eigen/Geometry>

#include <cmath>

#include "mesher/geometry/AdaptivePolyline.h"
#include "mesher/geometry/AdaptiveQuadrature.h"
#include "mesher/geometry/CurveProjection.h"

namespace aniso {

double ParametricCurve3d::project(const Vec3& p, double ts, double t0, double t1) const {
  const auto eval = [&](double t) {
    const Curve3dD2 d = d2(t);
    const Vec3 r = d.p - p;
    return DistanceSample{0.5 * r.squaredNorm(), r.dot(d.d1), d.d1.squaredNorm() + r.dot(d.d2),
                          r.norm() * d.d1.norm()};
  };
  return nearestParameter(eval, ts, t0, t1);
}

double ParametricCurve3d::length(double t0, double t1) const {
  return std::abs(integrateAdaptive([this](double t) { return d2(t).d1.norm(); }, t0, t1));
}

double ParametricCurve3d::length(double t0, double t1,
                                 const std::function<Mat3(const Vec3&)>& transform) const {
  const auto speed = [&](double t) {
    const Curve3dD2 d = d2(t);
    return (transform(d.p) * d.d1).norm();
  };
  return std::abs(integrateAdaptive(speed, t0, t1));
}

std::vector<double> ParametricCurve3d::polyline(double t0, double t1, double tol) const {
  return adaptivePolyline([this](double t) { return point(t); }, t0, t1, tol);
}

double ParametricCurve3d::curvature(double t) const {
  const Curve3dD2 c = d2(t);
  const double speed = c.d1.norm();
  if (!(speed > 0) || !std::isfinite(speed)) return 0;
  const double k = c.d1.cross(c.d2).norm() / (speed * speed * speed);
  return std::isfinite(k) ? k : 0;
}

}  // namespace aniso
