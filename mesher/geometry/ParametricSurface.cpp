// General methods of ParametricSurface (thesis sec. 2.2.1, 2.4.2, 6.2.1).
#include "mesher/geometry/ParametricSurface.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aniso {

namespace {

/// Relative threshold below which |pu × pv| counts as a singular point.
constexpr double kSingularRatio = 1e-12;
/// Relative threshold below which det G counts as singular for the curvature.
constexpr double kSingularMetric = 1e-14;

bool finite(const Vec3& v) { return v.allFinite(); }

/// Extent of a domain side, made usable as a length scale (infinite or absurd ranges of
/// unbounded surfaces fall back to 1).
double usableExtent(double a, double b) {
  const double e = b - a;
  return (std::isfinite(e) && e > 0 && e < 1e12) ? e : 1.0;
}

/// A point moved from uv towards the domain centre by a fraction `s` of the domain size.
Vec2 towardsCentre(const SurfaceDomain& d, const Vec2& uv, double s) {
  const double eu = usableExtent(d.u0, d.u1), ev = usableExtent(d.v0, d.v1);
  const bool finiteDomain = std::isfinite(d.u1 - d.u0) && std::isfinite(d.v1 - d.v0);
  Vec2 dir = finiteDomain ? Vec2(0.5 * (d.u0 + d.u1) - uv.x(), 0.5 * (d.v0 + d.v1) - uv.y())
                          : Vec2(-uv.x(), -uv.y());
  dir = Vec2(dir.x() / eu, dir.y() / ev);  // in domain-relative units
  if (!(dir.norm() > 1e-9)) dir = Vec2(1, 1);
  dir.normalize();
  return uv + s * Vec2(dir.x() * eu, dir.y() * ev);
}

bool regular(const SurfaceD1& d) {
  const double scale = d.pu.squaredNorm() + d.pv.squaredNorm();
  const double n = d.pu.cross(d.pv).norm();
  return std::isfinite(n) && scale > 0 && n > kSingularRatio * scale;
}

/// Any unit vector perpendicular to the non-zero one of a, b (last resort for the normal).
Vec3 anyPerpendicular(const Vec3& a, const Vec3& b) {
  const Vec3 t = (finite(a) && a.norm() >= (finite(b) ? b.norm() : 0.0)) ? a : b;
  if (!finite(t) || t.norm() == 0) return Vec3::UnitZ();
  const Vec3 axis = std::abs(t.x()) < 0.9 * t.norm() ? Vec3::UnitX() : Vec3::UnitY();
  return t.cross(axis).normalized();
}

/// A regular point near uv: uv itself when regular, else the nearest of a sequence of
/// points towards the domain centre. Returns false when none is regular.
bool regularNearby(const ParametricSurface& s, const Vec2& uv, Vec2& out) {
  if (regular(s.d1(uv))) { out = uv; return true; }
  const SurfaceDomain dom = s.domain();
  for (double step = 1e-7; step < 0.2; step *= 4) {
    const Vec2 q = towardsCentre(dom, uv, step);
    if (regular(s.d1(q))) { out = q; return true; }
  }
  return false;
}

/// Clamp the non-periodic parameters into the domain.
Vec2 clampToDomain(const SurfaceDomain& d, Vec2 uv) {
  if (!d.uPeriodic) uv.x() = std::clamp(uv.x(), std::min(d.u0, d.u1), std::max(d.u0, d.u1));
  if (!d.vPeriodic) uv.y() = std::clamp(uv.y(), std::min(d.v0, d.v1), std::max(d.v0, d.v1));
  return uv;
}

/// The Levenberg–Marquardt iteration of ParametricSurface::project from s (see there).
/// `best` always holds the best point found so far, also when an evaluation throws.
Vec2 descendFrom(const ParametricSurface& surf, const SurfaceDomain& dom, const Vec3& x, Vec2& best) {
  const double eu = usableExtent(dom.u0, dom.u1), ev = usableExtent(dom.v0, dom.v1);
  Vec2& s = best;
  SurfaceD2 d = surf.d2(s);
  if (!finite(d.p)) return s;
  double f = 0.5 * (d.p - x).squaredNorm();
  double lambda = 1e-3;
  for (int it = 0; it < 200 && f > 0; ++it) {
    const Vec3 r = d.p - x;
    const Vec2 grad(d.pu.dot(r), d.pv.dot(r));
    Mat2 h;
    h(0, 0) = d.pu.dot(d.pu) + r.dot(d.puu);
    h(0, 1) = h(1, 0) = d.pu.dot(d.pv) + r.dot(d.puv);
    h(1, 1) = d.pv.dot(d.pv) + r.dot(d.pvv);
    const double hs = std::max({std::abs(h(0, 0)), std::abs(h(1, 1)), d.pu.squaredNorm(),
                                d.pv.squaredNorm(), std::numeric_limits<double>::min()});
    const Vec2 diag(std::max(std::abs(h(0, 0)), 1e-10 * hs), std::max(std::abs(h(1, 1)), 1e-10 * hs));
    bool accepted = false;
    for (int tries = 0; tries < 40 && !accepted; ++tries) {
      Mat2 a = h;
      a(0, 0) += lambda * diag.x();
      a(1, 1) += lambda * diag.y();
      const double det = a.determinant();
      const bool pd = a(0, 0) > 0 && det > 1e-14 * a(0, 0) * a(1, 1);
      if (!pd) { lambda = std::max(lambda * 10, 1e-6); continue; }
      const Vec2 step = -a.inverse() * grad;
      // Converged when the step is negligible relative to the domain and the position.
      if (std::abs(step.x()) <= 1e-14 * std::max(eu, std::abs(s.x())) &&
          std::abs(step.y()) <= 1e-14 * std::max(ev, std::abs(s.y())))
        return s;
      const Vec2 sn = clampToDomain(dom, s + step);
      if (sn == s) return s;  // blocked by the domain boundary
      const SurfaceD2 dn = surf.d2(sn);
      if (!finite(dn.p)) { lambda *= 10; continue; }
      // Change of f computed as ½ (pn − p)·(rn + r), more accurate than a difference of two
      // squared norms. When it is within the round-off of the points (|p| ε |r|), f cannot
      // decide any more and the step is judged by the gradient norm instead.
      const Vec3 rn = dn.p - x;
      const double change = 0.5 * (dn.p - d.p).dot(rn + r);
      const double noise = 16 * std::numeric_limits<double>::epsilon() *
                           (d.p.norm() + x.norm()) * (r.norm() + rn.norm());
      bool better = change < -noise;
      if (!better && change <= noise) {
        const Vec2 gradN(dn.pu.dot(rn), dn.pv.dot(rn));
        better = gradN.norm() < grad.norm();
      }
      if (better) {
        s = sn;
        d = dn;
        f = 0.5 * rn.squaredNorm();
        lambda = std::max(lambda * 0.3, 1e-12);
        accepted = true;
      } else {
        lambda *= 10;
        if (lambda > 1e16) return s;
      }
    }
    if (!accepted) return s;
  }
  return s;
}

}  // namespace

double PrincipalCurvatures::maxAbs() const { return std::max(std::abs(k1), std::abs(k2)); }

Vec3 ParametricSurface::normal(const Vec2& uv) const {
  const SurfaceD1 d = d1(uv);
  if (regular(d)) return d.pu.cross(d.pv).normalized();
  Vec2 q;
  if (regularNearby(*this, uv, q)) {
    const SurfaceD1 e = d1(q);
    return e.pu.cross(e.pv).normalized();
  }
  return anyPerpendicular(d.pu, d.pv);
}

Mat2 ParametricSurface::firstFundamentalForm(const Vec2& uv) const {
  const SurfaceD1 d = d1(uv);
  Mat2 g;
  g(0, 0) = d.pu.dot(d.pu);
  g(0, 1) = g(1, 0) = d.pu.dot(d.pv);
  g(1, 1) = d.pv.dot(d.pv);
  return g;
}

Mat2 ParametricSurface::secondFundamentalForm(const Vec2& uv) const {
  const SurfaceD2 d = d2(uv);
  const Vec3 n = normal(uv);
  Mat2 b;
  b(0, 0) = n.dot(d.puu);
  b(0, 1) = b(1, 0) = n.dot(d.puv);
  b(1, 1) = n.dot(d.pvv);
  return b;
}

PrincipalCurvatures ParametricSurface::curvature(const Vec2& uv) const {
  // At a singular point (pole) G is singular: the curvature is taken at a nearby regular
  // point, where it tends to its limit value.
  Vec2 q = uv;
  Mat2 g = firstFundamentalForm(q);
  if (!(g.determinant() > kSingularMetric * g.trace() * g.trace())) regularNearby(*this, uv, q);
  g = firstFundamentalForm(q);
  const SurfaceD2 d = d2(q);
  const Mat2 b = secondFundamentalForm(q);
  PrincipalCurvatures pc;
  const double det = g.determinant();
  if (!(det > 0) || !std::isfinite(det) || !b.allFinite()) return pc;

  // det(B − χG) = 0 via the Cholesky factor G = L Lᵀ: C = L⁻¹ B L⁻ᵀ is symmetric, its
  // eigenvalues are χ and its orthonormal eigenvectors w give G-orthonormal y = L⁻ᵀ w.
  const double l11 = std::sqrt(g(0, 0)), l21 = g(1, 0) / l11;
  const double l22 = std::sqrt(std::max(g(1, 1) - l21 * l21, det / g(0, 0)));
  Mat2 linv;
  linv << 1 / l11, 0, -l21 / (l11 * l22), 1 / l22;
  const Mat2 c = linv * b * linv.transpose();
  const double a = c(0, 0), cc = c(1, 1), off = 0.5 * (c(0, 1) + c(1, 0));
  const double mean = 0.5 * (a + cc);
  const double rad = std::hypot(0.5 * (a - cc), off);
  pc.k1 = mean - rad;
  pc.k2 = mean + rad;

  Vec2 y1, y2;
  const double scale = std::max({std::abs(a), std::abs(cc), std::abs(off)});
  if (!(rad > 1e-10 * scale) || scale == 0) {
    // Umbilic: the u direction and its G-orthogonal complement.
    y1 = Vec2(1, 0);
    y2 = Vec2(-g(0, 1), g(0, 0));
  } else {
    // Eigenvector of C for k2, taken from the better-conditioned row of (C − k2 I).
    const Vec2 ea(off, pc.k2 - a), eb(pc.k2 - cc, off);
    const Vec2 w2 = (ea.squaredNorm() >= eb.squaredNorm() ? ea : eb).normalized();
    const Vec2 w1(w2.y(), -w2.x());
    y1 = linv.transpose() * w1;
    y2 = linv.transpose() * w2;
  }
  pc.dir1 = y1.normalized();
  pc.dir2 = y2.normalized();
  pc.d3_1 = (d.pu * pc.dir1.x() + d.pv * pc.dir1.y()).normalized();
  pc.d3_2 = (d.pu * pc.dir2.x() + d.pv * pc.dir2.y()).normalized();
  return pc;
}

Mat2 ParametricSurface::parameterizationTensor(const Vec2& uv, double gMin) const {
  Mat2 g = firstFundamentalForm(uv);
  // Guard (sec. 2.2.1): g11, g22 raised to gMin; a tiny floor relative to the larger one
  // keeps the tensor positive definite even when gMin is 0.
  const double big = std::max(g(0, 0), g(1, 1));
  const double floor = std::max({gMin, 1e-14 * big, std::numeric_limits<double>::min() * 1e20});
  g(0, 0) = std::max(g(0, 0), floor);
  g(1, 1) = std::max(g(1, 1), floor);
  // Keep det G > 0: |g12| strictly below sqrt(g11 g22).
  const double lim = (1 - 1e-12) * std::sqrt(g(0, 0) * g(1, 1));
  const double g12 = std::clamp(0.5 * (g(0, 1) + g(1, 0)), -lim, lim);
  g(0, 1) = g(1, 0) = g12;
  // Symmetric square root of a 2×2 SPD matrix (Cayley–Hamilton):
  // sqrt(G) = (G + s I) / t, s = sqrt(det G), t = sqrt(tr G + 2 s).
  const double s = std::sqrt(std::max(g.determinant(), 0.0));
  const double t = std::sqrt(g.trace() + 2 * s);
  return (g + s * Mat2::Identity()) / t;
}

Vec2 ParametricSurface::project(const Vec3& x, const Vec2& start) const {
  // Levenberg–Marquardt on f(s) = ½|p(s) − x|² with the exact Hessian
  // JᵀJ + Σ r·p_ij (quadratic convergence also for points off the surface), Marquardt
  // scaling of the damping (robust where pu or pv vanish, at poles) and acceptance only of
  // steps that decrease f, or at round-off level |∇f| (backtracking by raising the damping).
  Vec2 s = start;
  try {
    const SurfaceDomain dom = domain();
    s = clampToDomain(dom, start);
    if (!s.allFinite()) s = Vec2(0.5 * (dom.u0 + dom.u1), 0.5 * (dom.v0 + dom.v1));
    if (!x.allFinite()) return s;
    return descendFrom(*this, dom, x, s);
  } catch (...) {
    return s;  // an evaluation threw: the best point so far (the contract: never throws)
  }
}

}  // namespace aniso
