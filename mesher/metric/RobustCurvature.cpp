#include "mesher/metric/RobustCurvature.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesher/metric/SurfaceCurvatureMetric.h"

namespace aniso {
namespace {

/// Refits of the parametric step so that the sample lies at the 3D distance h.
constexpr int kStepFits = 3;

/// uv clamped into the box.
Vec2 clampInto(const Box2& box, const Vec2& uv) { return uv.cwiseMax(box.lo).cwiseMin(box.hi); }

/// A sample on the surface about h away from p towards uv + t·d (the target clamped into the
/// box, so that a point on the box's side or corner still has samples inside), or false when
/// the box leaves no room in that sense.
bool sampleAt(const ParametricSurface& s, const Vec2& uv, const Vec3& p, const Vec2& d, double speed, double h,
              const Box2& box, Vec3& q) {
  const double span = box.diagonal();
  const auto target = [&](double t) { return clampInto(box, uv + t * d); };
  double t = speed > 0 ? std::min(h / speed, span) : span;
  if (!((target(t) - uv).norm() > 1e-9 * span)) return false;
  for (int k = 0; k < kStepFits; ++k) {
    q = s.point(target(t));
    const double dist = (q - p).norm();
    if (!(dist > 0) || !q.allFinite()) return false;
    const double next = std::min(t * h / dist, span);
    if (std::abs(next - t) <= 0.02 * t) break;
    t = next;
  }
  q = s.point(target(t));
  return q.allFinite() && (q - p).norm() > 0;
}

}  // namespace

RobustCurvatureBounds RobustCurvatureBounds::of(const Box2& uv, const CurvatureSizing& sizing, double tolerance,
                                                double faceWidth) {
  RobustCurvatureBounds b;
  b.uv = uv;
  b.floor = std::max({sizing.hMin, kToleranceFactor * std::max(tolerance, 0.0),
                      sizing.curvatureRatio * kMinRadiusFraction * (std::isfinite(faceWidth) ? faceWidth : 0.0)});
  b.floor = std::min(b.floor, sizing.hMax);
  return b;
}

double secantCurvature(const ParametricSurface& surface, const Vec2& uv, const Vec3& n, const Vec2 (&dirs)[kSecantLines],
                       double h, const Box2& box) {
  const SurfaceD1 d = surface.d1(uv);
  double kappa = -1;
  for (const Vec2& dir : dirs) {
    const double speed = (d.pu * dir.x() + d.pv * dir.y()).norm();
    Vec3 qp, qm;
    const bool plus = sampleAt(surface, uv, d.p, dir, speed, h, box, qp);
    const bool minus = sampleAt(surface, uv, d.p, -dir, speed, h, box, qm);
    if (!plus && !minus) continue;
    double k = 0;
    if (plus && minus)
      k = 2 * std::abs(n.dot(qp - d.p) + n.dot(qm - d.p)) / ((qp - d.p).squaredNorm() + (qm - d.p).squaredNorm());
    else {
      const Vec3 q = plus ? qp : qm;
      k = 2 * std::abs(n.dot(q - d.p)) / (q - d.p).squaredNorm();
    }
    if (std::isfinite(k)) kappa = std::max(kappa, k);
  }
  return kappa;
}

Metric2d robustCurvatureSizing(const ParametricSurface& surface, const Vec2& uv, double gMin,
                               const CurvatureSizing& sizing, const RobustCurvatureBounds& bounds) {
  sizing.check();
  const PrincipalCurvatures pc = surface.curvature(uv);
  Vec2 h(sizing.length(pc.k1), sizing.length(pc.k2));  // eq. 2.41
  double hr = std::max(h.minCoeff(), bounds.floor);
  if (hr < sizing.hMax) {
    const Vec2 b1 = (pc.dir1 + pc.dir2).normalized(), b2 = (pc.dir1 - pc.dir2).normalized();
    const Vec2 dirs[kSecantLines] = {pc.dir1, pc.dir2, b1.allFinite() ? b1 : pc.dir1, b2.allFinite() ? b2 : pc.dir2};
    const Vec3 n = surface.normal(uv);
    for (int step = 0; step < kSecantSteps && hr < sizing.hMax; ++step) {
      const double ks = secantCurvature(surface, uv, n, dirs, hr, bounds.uv);
      if (ks < 0) break;  // no sample: the point curvature stands
      const double asked = sizing.length(ks);
      if (!(asked > (1 + kSecantSlack) * hr)) break;
      hr = std::min(asked, sizing.hMax);
    }
  }
  h = h.cwiseMax(Vec2::Constant(hr));
  return principalSizing(pc, surface.parameterizationTensor(uv, gMin), h, sizing.anisotropy);
}

}  // namespace aniso
