// General methods of ParametricCurve2d (thesis sec. 2.4.3, 6.2.2).
#include "mesher/geometry/ParametricCurve2d.h"

#include <Eigen/Geometry>

#include <cmath>

#include "mesher/geometry/AdaptivePolyline.h"
#include "mesher/geometry/AdaptiveQuadrature.h"
#include "mesher/geometry/CurveProjection.h"
#include "mesher/geometry/ParametricSurface.h"

namespace aniso {

double ParametricCurve2d::project(const Vec2& p, double ts, double t0, double t1) const {
  const auto eval = [&](double t) {
    const Curve2dD2 d = d2(t);
    const Vec2 r = d.p - p;
    return DistanceSample{0.5 * r.squaredNorm(), r.dot(d.d1), d.d1.squaredNorm() + r.dot(d.d2),
                          r.norm() * d.d1.norm()};
  };
  return nearestParameter(eval, ts, t0, t1);
}

double ParametricCurve2d::length(double t0, double t1) const {
  return std::abs(integrateAdaptive([this](double t) { return d2(t).d1.norm(); }, t0, t1));
}

double ParametricCurve2d::length(double t0, double t1,
                                 const std::function<Mat2(const Vec2&)>& transform) const {
  const auto speed = [&](double t) {
    const Curve2dD2 d = d2(t);
    return (transform(d.p) * d.d1).norm();
  };
  return std::abs(integrateAdaptive(speed, t0, t1));
}

std::vector<double> ParametricCurve2d::polyline(double t0, double t1,
                                                const ParametricSurface* surface,
                                                double tol) const {
  if (surface) return adaptivePolyline([&](double t) { return surface->point(point(t)); }, t0, t1, tol);
  return adaptivePolyline([&](double t) { const Vec2 q = point(t); return Vec3(q.x(), q.y(), 0.0); },
                          t0, t1, tol);
}

double ParametricCurve2d::curvature(double t, const ParametricSurface& surface) const {
  // Chain rule for c = p∘c_p: c' = pu u' + pv v',
  // c'' = puu u'² + 2 puv u'v' + pvv v'² + pu u'' + pv v''.
  const Curve2dD2 c = d2(t);
  const SurfaceD2 s = surface.d2(c.p);
  const double du = c.d1.x(), dv = c.d1.y();
  const Vec3 d1 = s.pu * du + s.pv * dv;
  const Vec3 dd = s.puu * du * du + 2 * s.puv * du * dv + s.pvv * dv * dv + s.pu * c.d2.x() +
                  s.pv * c.d2.y();
  const double speed = d1.norm();
  if (!(speed > 0) || !std::isfinite(speed)) return 0;
  const double k = d1.cross(dd).norm() / (speed * speed * speed);
  return std::isfinite(k) ? k : 0;
}

}  // namespace aniso
