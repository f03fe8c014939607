// Tests of the metric sources (sec. 2.4): simplex metric (2.33–2.34), surface curvature
// (2.35–2.42) and contour curvature (2.45–2.46).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <memory>
#include <random>

#include "mesher/core/Error.h"
#include "mesher/metric/ContourCurvatureMetric.h"
#include "mesher/metric/MeanRatio.h"
#include "mesher/metric/SimplexMetric.h"
#include "mesher/metric/SurfaceCurvatureMetric.h"
#include "mesher/metric/SurfaceMetric.h"

using namespace aniso;

namespace {

/// Sphere of radius r: p = r (cos v cos u, cos v sin u, sin v).
class TestSphere final : public ParametricSurface {
 public:
  explicit TestSphere(double r) : r_(r) {}
  Vec3 point(const Vec2& s) const override { return d1(s).p; }
  SurfaceD1 d1(const Vec2& s) const override {
    const SurfaceD2 d = d2(s);
    return {d.p, d.pu, d.pv};
  }
  SurfaceD2 d2(const Vec2& s) const override {
    const double cu = std::cos(s.x()), su = std::sin(s.x()), cv = std::cos(s.y()), sv = std::sin(s.y());
    SurfaceD2 d;
    d.p = r_ * Vec3(cv * cu, cv * su, sv);
    d.pu = r_ * Vec3(-cv * su, cv * cu, 0);
    d.pv = r_ * Vec3(-sv * cu, -sv * su, cv);
    d.puu = r_ * Vec3(-cv * cu, -cv * su, 0);
    d.puv = r_ * Vec3(sv * su, -sv * cu, 0);
    d.pvv = r_ * Vec3(-cv * cu, -cv * su, -sv);
    return d;
  }
  SurfaceDomain domain() const override { return {0, 2 * M_PI, -M_PI / 2, M_PI / 2, true, false, 2 * M_PI, 0}; }
  std::unique_ptr<ParametricSurface> clone() const override { return std::make_unique<TestSphere>(*this); }

 private:
  double r_;
};

/// Cylinder of radius r with a sheared parameterization: p = (r cos u, r sin u, v + c u).
/// c = 0 is the usual orthogonal parameterization; c ≠ 0 makes G non-diagonal.
class TestCylinder final : public ParametricSurface {
 public:
  TestCylinder(double r, double c) : r_(r), c_(c) {}
  Vec3 point(const Vec2& s) const override { return d1(s).p; }
  SurfaceD1 d1(const Vec2& s) const override {
    const SurfaceD2 d = d2(s);
    return {d.p, d.pu, d.pv};
  }
  SurfaceD2 d2(const Vec2& s) const override {
    const double cu = std::cos(s.x()), su = std::sin(s.x());
    SurfaceD2 d;
    d.p = Vec3(r_ * cu, r_ * su, s.y() + c_ * s.x());
    d.pu = Vec3(-r_ * su, r_ * cu, c_);
    d.pv = Vec3(0, 0, 1);
    d.puu = Vec3(-r_ * cu, -r_ * su, 0);
    d.puv = Vec3::Zero();
    d.pvv = Vec3::Zero();
    return d;
  }
  SurfaceDomain domain() const override { return {0, 2 * M_PI, -10, 10, true, false, 2 * M_PI, 0}; }
  std::unique_ptr<ParametricSurface> clone() const override { return std::make_unique<TestCylinder>(*this); }

 private:
  double r_, c_;
};

/// The plane p = (u, v, 0).
class TestPlane final : public ParametricSurface {
 public:
  Vec3 point(const Vec2& s) const override { return Vec3(s.x(), s.y(), 0); }
  SurfaceD1 d1(const Vec2& s) const override { return {point(s), Vec3::UnitX(), Vec3::UnitY()}; }
  SurfaceD2 d2(const Vec2& s) const override {
    return {point(s), Vec3::UnitX(), Vec3::UnitY(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  }
  SurfaceDomain domain() const override { return {-10, 10, -10, 10, false, false, 0, 0}; }
  std::unique_ptr<ParametricSurface> clone() const override { return std::make_unique<TestPlane>(*this); }
};

/// Circle of radius r in the parametric plane.
class TestCircle final : public ParametricCurve2d {
 public:
  explicit TestCircle(double r) : r_(r) {}
  Vec2 point(double t) const override { return r_ * Vec2(std::cos(t), std::sin(t)); }
  Curve2dD2 d2(double t) const override {
    const double c = std::cos(t), s = std::sin(t);
    return {r_ * Vec2(c, s), r_ * Vec2(-s, c), r_ * Vec2(-c, -s)};
  }
  double tMin() const override { return 0; }
  double tMax() const override { return 2 * M_PI; }
  std::unique_ptr<ParametricCurve2d> clone() const override { return std::make_unique<TestCircle>(*this); }

 private:
  double r_;
};

CurvatureSizing sizing(double hMin, double hMax, double gammaA = 5, double gammaAc = 2) {
  CurvatureSizing s;
  s.curvatureRatio = 0.15;
  s.hMin = hMin;
  s.hMax = hMax;
  s.anisotropy = gammaA;
  s.contourAnisotropy = gammaAc;
  return s;
}

}  // namespace

// ---- simplex ----

TEST(MetricSimplex, EquilateralUnitSimplexGivesIdentity) {
  const Vec2 a(0.3, -1), b = a + Vec2(1, 0), c = a + Vec2(0.5, std::sqrt(3.0) / 2);
  EXPECT_LT((simplexMetricTensor(a, b, c) - Mat2::Identity()).norm(), 1e-14);
  EXPECT_LT((simplexMetric(a, b, c).matrix() - Mat2::Identity()).norm(), 1e-14);
  // Regular tetrahedron with unit edges, rotated and moved.
  const Vec3 p1(0, 0, 0), p2(1, 0, 0), p3(0.5, std::sqrt(3.0) / 2, 0),
      p4(0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3));
  const Mat3 r = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 o(5, -2, 1);
  const Metric3d m = simplexMetric(Vec3(o + r * p1), Vec3(o + r * p2), Vec3(o + r * p3), Vec3(o + r * p4));
  EXPECT_LT((m.matrix() - Mat3::Identity()).norm(), 1e-13);
  // Twice as big: the identity halved.
  EXPECT_LT((simplexMetric(Vec2(2 * a), Vec2(2 * b), Vec2(2 * c)).matrix() - 0.5 * Mat2::Identity()).norm(), 1e-14);
}

TEST(MetricSimplex, SolvesEquation234AndMakesAnySimplexEquilateral) {
  std::mt19937 rng(37);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int k = 0; k < 100; ++k) {
    const Vec2 a(u(rng), u(rng)), b(u(rng), u(rng)), c(u(rng), u(rng));
    if (std::abs(meanRatio(a, b, c)) < 0.05) continue;  // skip nearly flat ones
    const Mat2 t = simplexMetricTensor(a, b, c);
    // Independent check: the 3×3 system of eq. 2.34.
    Mat3 sys;
    const Vec2 e[3] = {b - a, c - a, c - b};
    for (int i = 0; i < 3; ++i) sys.row(i) << e[i].x() * e[i].x(), 2 * e[i].x() * e[i].y(), e[i].y() * e[i].y();
    const Vec3 m = sys.partialPivLu().solve(Vec3::Ones());
    EXPECT_NEAR(t(0, 0), m(0), 1e-8 * t.norm());
    EXPECT_NEAR(t(0, 1), m(1), 1e-8 * t.norm());
    EXPECT_NEAR(t(1, 1), m(2), 1e-8 * t.norm());
    // Every edge has unit metric length; η_M = ±1 (sign = orientation).
    const Metric2d mk = simplexMetric(a, b, c);
    for (const Vec2& v : e) EXPECT_NEAR(mk.length(v), 1.0, 1e-10);
    EXPECT_NEAR(std::abs(meanRatio(mk, a, b, c)), 1.0, 1e-10);
    EXPECT_GT(meanRatio(mk, a, b, c) * meanRatio(a, b, c), 0);  // orientation kept
  }
  for (int k = 0; k < 100; ++k) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng)),
        d(u(rng), u(rng), u(rng));
    if (std::abs(meanRatio(a, b, c, d)) < 0.05) continue;
    const Metric3d mk = simplexMetric(a, b, c, d);
    const Vec3 e[6] = {b - a, c - a, d - a, c - b, d - b, d - c};
    for (const Vec3& v : e) EXPECT_NEAR(mk.length(v), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(meanRatio(mk, a, b, c, d)), 1.0, 1e-9);
  }
}

TEST(MetricSimplex, DegenerateSimplexThrows) {
  EXPECT_THROW(simplexMetric(Vec2(0, 0), Vec2(1, 1), Vec2(2, 2)), MeshingError);
  EXPECT_THROW(simplexMetric(Vec2(0, 0), Vec2(0, 0), Vec2(0, 0)), MeshingError);
  EXPECT_THROW(simplexMetric(Vec2(0, 0), Vec2(1, 0), Vec2(std::nan(""), 1)), MeshingError);
  EXPECT_THROW(simplexMetric(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)), MeshingError);
}

// ---- surface curvature ----

TEST(MetricCurvature, LengthLaw241) {
  const CurvatureSizing s = sizing(0.01, 1.0);
  EXPECT_NEAR(s.length(1.0), 0.15, 1e-15);
  EXPECT_NEAR(s.length(-2.0), 0.075, 1e-15);  // sign irrelevant
  EXPECT_EQ(s.length(0.0), 1.0);              // flat: h_max
  EXPECT_EQ(s.length(0.1), 1.0);              // 1.5 clamped to h_max
  EXPECT_EQ(s.length(100.0), 0.01);           // 0.0015 clamped to h_min
  EXPECT_THROW(s.length(std::nan("")), MeshingError);
  CurvatureSizing bad = s;
  bad.contourAnisotropy = 10;  // > γ_a
  EXPECT_THROW(bad.check(), MeshingError);
  bad = s;
  bad.hMax = 0.001;
  EXPECT_THROW(bad.check(), MeshingError);
}

TEST(MetricCurvature, ChordDeviationBoundsLargeRadii) {
  CurvatureSizing s = sizing(0.001, 10.0);
  s.curvatureRatio = 2 * std::acos(-1.0) / 12;  // 12 per circle
  s.chordDeviation = 0.002;
  // radius 100: γ_c R = 52.4 > h_max; the chord bound sqrt(8 δ R) = 1.26 wins; its
  // sagitta h²/(8R) is δ
  const double h = s.length(0.01);
  EXPECT_NEAR(h, std::sqrt(8 * 0.002 * 100), 1e-12);
  EXPECT_NEAR(h * h / (8 * 100), 0.002, 1e-15);
  // radius 0.01: γ_c R = 0.00524 is below the chord bound (0.0127): eq. 2.41 stands
  EXPECT_NEAR(s.length(100.0), s.curvatureRatio / 100.0, 1e-15);
  EXPECT_EQ(s.length(0.0), 10.0);  // flat: h_max, no division
  s.chordDeviation = 0;            // off: eq. 2.41 alone (h_max here)
  EXPECT_EQ(s.length(0.01), 10.0);
  s.chordDeviation = -1;
  EXPECT_THROW(s.check(), MeshingError);
  SizingParameters p;
  p.chordDeviationRel = 1e-3;
  EXPECT_DOUBLE_EQ(CurvatureSizing::from(p, 50.0).chordDeviation, 0.05);
  EXPECT_DOUBLE_EQ(CurvatureSizing::from(SizingParameters{}, 50.0).chordDeviation, 0.0);  // the thesis' table
}

TEST(MetricCurvature, FromSizingParameters) {
  SizingParameters p;
  p.contourAnisotropy = 9;  // above γ_a = 5: capped
  const CurvatureSizing s = CurvatureSizing::from(p, 10.0);
  EXPECT_DOUBLE_EQ(s.hMax, 5.0);
  EXPECT_DOUBLE_EQ(s.hMin, 1e-3);
  EXPECT_DOUBLE_EQ(s.contourAnisotropy, 5.0);
  EXPECT_DOUBLE_EQ(s.curvatureRatio, 0.15);
}

TEST(MetricCurvature, SphereIsIsotropicWithGammaCTimesRadius) {
  for (double radius : {0.01, 1.0, 2.0, 100.0}) {
    const TestSphere sphere(radius);
    const CurvatureSizing s = sizing(0.01, 1.0);
    const double h = std::clamp(0.15 * radius, 0.01, 1.0);
    for (const Vec2& uv : {Vec2(0.7, 0.3), Vec2(2.0, -1.0), Vec2(4.0, 1.2)}) {
      const Metric2d ms = surfaceCurvatureSizing(sphere, uv, 0.0, s);
      // M_s = I / h: isotropic on the surface.
      EXPECT_LT((ms.matrix() - Mat2::Identity() / h).norm(), 1e-9 / h) << radius;
      // Full transformation: a parametric vector of surface length h has metric length 1.
      const Mat2 m = surfaceTransformation(ms, sphere.parameterizationTensor(uv, 0.0));
      const SurfaceD1 d = sphere.d1(uv);
      for (const Vec2& x : {Vec2(1, 0), Vec2(0, 1), Vec2(0.3, -0.8)}) {
        const double surfaceLength = (d.pu * x.x() + d.pv * x.y()).norm();
        EXPECT_NEAR((m * x).norm(), surfaceLength / h, 1e-9 * surfaceLength / h);
      }
    }
  }
}

TEST(MetricCurvature, CylinderIsStretchedAlongAxisWithinAnisotropyLimit) {
  const double radius = 1.0;
  const CurvatureSizing s = sizing(0.01, 10.0, 5.0);
  const double hCirc = 0.15 * radius, hAxis = std::min(10.0, 5.0 * hCirc);  // eq. 2.41, 2.42
  for (double shear : {0.0, 0.8, -2.5}) {
    const TestCylinder cyl(radius, shear);
    const Vec2 uv(0.9, 0.4);
    const Mat2 mp = cyl.parameterizationTensor(uv, 0.0);
    const Metric2d ms = surfaceCurvatureSizing(cyl, uv, 0.0, s);
    const MetricAngle2d a = ms.angleLengths();
    EXPECT_NEAR(a.h1, hCirc, 1e-9);
    EXPECT_NEAR(a.h2, hAxis, 1e-9);
    const Mat2 m = surfaceTransformation(ms, mp);
    // Circumferential parametric direction (1, −c): surface length r, metric r / h_circ.
    EXPECT_NEAR((m * Vec2(1, -shear)).norm(), radius / hCirc, 1e-8) << shear;
    // Axial parametric direction (0, 1): surface length 1, metric 1 / h_axis.
    EXPECT_NEAR((m * Vec2(0, 1)).norm(), 1 / hAxis, 1e-8) << shear;
  }
}

TEST(MetricCurvature, DirectionIsMeasuredInRealSpace) {
  // Principal direction y1 = (1, −1) with a non-diagonal M_p: the small length lies along
  // M_p y1 in S^R, not along y1.
  Mat2 mp;
  mp << 1.5, 0.6, 0.6, 1.0;
  const Mat2 g = mp * mp;
  PrincipalCurvatures pc;
  pc.k1 = 10;
  pc.k2 = 0;
  pc.dir1 = Vec2(1, -1).normalized();
  // A G-orthogonal partner (not used by the source, which takes the S^R perpendicular).
  pc.dir2 = Vec2(-(g * pc.dir1).y(), (g * pc.dir1).x()).normalized();
  const CurvatureSizing s = sizing(0.001, 1.0, 100.0);
  const Metric2d ms = surfaceCurvatureSizing(pc, mp, s);
  const Mat2 m = surfaceTransformation(ms, mp);
  const double h1 = 0.015, h2 = 1.0;
  EXPECT_NEAR((m * pc.dir1).norm(), (mp * pc.dir1).norm() / h1, 1e-9);
  EXPECT_NEAR((m * pc.dir2).norm(), (mp * pc.dir2).norm() / h2, 1e-9);
  EXPECT_THROW(surfaceCurvatureSizing(pc, Mat2::Zero(), s), MeshingError);
}

// ---- contour curvature ----

TEST(MetricCurvature, ContourCircleOnPlane) {
  const TestPlane plane;
  const double r = 0.5;
  const TestCircle circle(r);
  const CurvatureSizing s = sizing(0.001, 1.0, 5.0, 2.0);
  const double h1 = 0.15 * r, h2 = 2.0 * h1;  // eq. 2.46
  for (double t : {0.0, 1.0, 2.5, 4.0}) {
    const Metric2d ms = contourCurvatureSizing(circle, t, plane, 0.0, s);
    const Vec2 tangent(-std::sin(t), std::cos(t)), normal(std::cos(t), std::sin(t));
    EXPECT_NEAR(ms.lengthAlong(tangent), h1, 1e-9) << t;  // h1 along the contour
    EXPECT_NEAR(ms.lengthAlong(normal), h2, 1e-9) << t;   // γ_ac h1 across
  }
}

TEST(MetricCurvature, ContourLengthsAndLimits) {
  const Mat2 mp = Mat2::Identity();
  const CurvatureSizing s = sizing(0.001, 1.0, 5.0, 3.0);
  // Straight contour: h1 = h_max; h2 = γ_ac h_max capped at h_max (interpretation).
  const Metric2d flat = contourCurvatureSizing(0.0, Vec2(1, 0), mp, s);
  EXPECT_LT((flat.matrix() - Mat2::Identity()).norm(), 1e-12);
  // Mild curvature: h1 = 0.5, γ_ac h1 = 1.5 capped at 1.
  const Metric2d mild = contourCurvatureSizing(0.3, Vec2(0, 2), mp, s);
  EXPECT_NEAR(mild.lengthAlong(Vec2(0, 1)), 0.5, 1e-12);
  EXPECT_NEAR(mild.lengthAlong(Vec2(1, 0)), 1.0, 1e-12);
  // Sheared M_p: the tangent direction is measured in S^R.
  Mat2 sh;
  sh << 2.0, 0.7, 0.7, 1.0;
  const Vec2 tangent(0.3, 1.0);
  const Metric2d ms = contourCurvatureSizing(15.0, tangent, sh, s);
  EXPECT_NEAR((surfaceTransformation(ms, sh) * tangent).norm(), (sh * tangent).norm() / 0.01, 1e-8);
  EXPECT_THROW(contourCurvatureSizing(1.0, Vec2::Zero(), mp, s), MeshingError);
  EXPECT_THROW(contourCurvatureSizing(std::nan(""), Vec2(1, 0), mp, s), MeshingError);
}
