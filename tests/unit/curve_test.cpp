// Curves: projection, lengths (Euclidean and metric), polylines and curvature, for the 2D
// pcurves (on surfaces) and the 3D curves.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesher/geometry/AdaptiveQuadrature.h"
#include "mesher/geometry/Circle2d.h"
#include "mesher/geometry/Circle3d.h"
#include "mesher/geometry/CurveOnSurface3d.h"
#include "mesher/geometry/CylinderSurface.h"
#include "mesher/geometry/Line2d.h"
#include "mesher/geometry/Line3d.h"
#include "mesher/geometry/PlaneSurface.h"

using namespace aniso;

namespace {

constexpr double kPi = std::numbers::pi;

const Frame kTilted(Vec3(1, -2, 0.5), Vec3(0.3, 0.2, 1.0), Vec3(1, 0.1, 0));

double distanceToSegment(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double s = std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (x - (a + s * ab)).norm();
}

/// Every piece of the polyline: dense samples stay within `bound` × chord of the chord.
template <class Point>
void checkPolyline(const std::vector<double>& ts, double t0, double t1, const Point& point, double bound) {
  ASSERT_GE(ts.size(), 2u);
  EXPECT_EQ(ts.front(), t0);
  EXPECT_EQ(ts.back(), t1);
  for (size_t i = 0; i + 1 < ts.size(); ++i) {
    EXPECT_GT((ts[i + 1] - ts[i]) * (t1 - t0), 0) << "monotone";
    const Vec3 a = point(ts[i]), b = point(ts[i + 1]);
    const double chord = (b - a).norm();
    for (int k = 1; k < 16; ++k) {
      const double t = ts[i] + (ts[i + 1] - ts[i]) * k / 16;
      EXPECT_LE(distanceToSegment(point(t), a, b), bound * chord + 1e-12);
    }
  }
}

}  // namespace

TEST(Quadrature, ExactForPolynomialsAccurateForSmoothFunctions) {
  EXPECT_NEAR(integrateAdaptive([](double x) { return std::pow(x, 20); }, -1, 2, 1e-13),
              (std::pow(2.0, 21) + 1) / 21, 1e-13 * std::pow(2.0, 21) / 21);
  EXPECT_NEAR(integrateAdaptive([](double x) { return std::exp(x); }, 0, 5, 1e-12), std::exp(5.0) - 1, 1e-9);
  EXPECT_NEAR(integrateAdaptive([](double x) { return std::sqrt(std::abs(x)); }, -1, 1, 1e-10), 4.0 / 3, 1e-8);
  EXPECT_NEAR(integrateAdaptive([](double x) { return x; }, 2, 0), -2, 1e-14);
}

TEST(Curve2d, CircleLengthAndProjection) {
  const double r = 0.75;
  const Circle2d c(Vec2(1, -2), r);
  EXPECT_NEAR(c.length(c.tMin(), c.tMax()), 2 * kPi * r, 1e-12);
  EXPECT_NEAR(c.length(1.0, 0.2), 0.8 * r, 1e-12);
  // Nearest point of a point outside / inside the circle.
  EXPECT_NEAR(c.project(Vec2(1, -2) + 3 * Vec2(std::cos(1.0), std::sin(1.0)), 0.5, 0, 2 * kPi), 1.0, 1e-12);
  EXPECT_NEAR(c.project(Vec2(1, -2) + 0.1 * Vec2(std::cos(4.0), std::sin(4.0)), 0.5, 0, 2 * kPi), 4.0, 1e-12);
  // The answer respects the range: outside it, the nearer end.
  EXPECT_NEAR(c.project(Vec2(1, -2) + Vec2(std::cos(3.0), std::sin(3.0)), 0.5, 0, 2.0), 2.0, 1e-12);
  // Near the wrap point the seam side nearest to the start wins a tie between 0 and 2π.
  EXPECT_NEAR(c.project(c.point(0), 6.2, 0, 2 * kPi), 2 * kPi, 1e-12);
  EXPECT_NEAR(c.project(c.point(0), 0.1, 0, 2 * kPi), 0, 1e-12);
  // The centre is equidistant from every point: the start is kept.
  EXPECT_NEAR(c.project(Vec2(1, -2), 2.5, 0, 2 * kPi), 2.5, 1e-12);
}

TEST(Curve2d, LineProjectionAndLength) {
  const Line2d l(Vec2(0, 0), Vec2(3, 4), 1, 3);
  EXPECT_NEAR(l.length(1, 3), 5, 1e-14);
  EXPECT_NEAR(l.project(Vec2(3, 4) * 0.5 + Vec2(-4, 3), 1, 1, 3), 2, 1e-14);
  EXPECT_DOUBLE_EQ(l.project(Vec2(10, 10), 2, 1, 3), 3);
  // The general method agrees with the exact override.
  EXPECT_NEAR(l.ParametricCurve2d::project(Vec2(1, 1), 1.5, 1, 3), l.project(Vec2(1, 1), 1.5, 1, 3), 1e-12);
}

TEST(Curve2d, MetricLength) {
  const Circle2d c(Vec2(0.2, 0.1), 0.5);
  // A constant transform: rotation × 3 scales every length by 3.
  Mat2 m;
  m << 3 * std::cos(0.4), -3 * std::sin(0.4), 3 * std::sin(0.4), 3 * std::cos(0.4);
  EXPECT_NEAR(c.length(0.3, 2.0, [&](const Vec2&) { return m; }), 3 * c.length(0.3, 2.0), 1e-12);
  // With M = M_p of a surface the metric length is the 3D length (plane with u scaled by 2:
  // the circle becomes an ellipse with semi-axes 1 and 0.5).
  auto plane = std::make_shared<PlaneSurface>(Vec3::Zero(), Vec3(2, 0, 0), Vec3(0, 1, 0), -1, 1, -1, 1);
  const double lm = c.length(0, 2 * kPi, [&](const Vec2& p) { return plane->parameterizationTensor(p, 0); });
  const CurveOnSurface3d image(plane, std::make_shared<Circle2d>(c));
  EXPECT_NEAR(lm, image.length(0, 2 * kPi), 1e-9);
  EXPECT_NEAR(lm, 4.844224110273838, 1e-9);  // perimeter of the ellipse a = 1, b = 0.5
}

TEST(Curve2d, PolylineDeviation) {
  const Circle2d c(Vec2(0, 0), 1.0);
  for (double tol : {1e-2, 1e-3}) {
    const auto ts = c.polyline(0, 2 * kPi, nullptr, tol);
    checkPolyline(ts, 0, 2 * kPi, [&](double t) { const Vec2 p = c.point(t); return Vec3(p.x(), p.y(), 0); }, 1.1 * tol);
    // Not over-refined: sagitta/chord ≈ θ/8, so about 2π/(8 tol) pieces.
    EXPECT_LT(ts.size(), 2 * 2 * kPi / (8 * tol) + 8);
  }
  // On a cylinder a straight pcurve along u is a circle in 3D: measured in 3D it needs
  // refinement, measured in (u,v) one piece suffices.
  const CylinderSurface cyl(kTilted, 2.0, -1, 1);
  const Line2d around(Vec2(0, 0.3), Vec2(2 * kPi, 0.3), 0, 1);
  const auto flat = around.polyline(0, 1, nullptr, 1e-3);
  EXPECT_LE(flat.size(), 5u);
  const auto onSurface = around.polyline(0, 1, &cyl, 1e-3);
  EXPECT_GT(onSurface.size(), 100u);
  checkPolyline(onSurface, 0, 1, [&](double t) { return cyl.point(around.point(t)); }, 1.1e-3);
  // Reversed range.
  const auto back = c.polyline(kPi, 0, nullptr, 1e-2);
  EXPECT_EQ(back.front(), kPi);
  EXPECT_EQ(back.back(), 0);
}

TEST(Curve2d, CurvatureOnSurfaces) {
  const PlaneSurface plane(Vec3(1, 2, 3), Vec3(0, 1, 0), Vec3(0, 0, 1), -5, 5, -5, 5);
  const Circle2d c(Vec2(0.5, 0.5), 0.4);
  for (double t : {0.0, 1.0, 4.0}) EXPECT_NEAR(c.curvature(t, plane), 1 / 0.4, 1e-12);
  EXPECT_NEAR(Line2d(Vec2(0, 0), Vec2(1, 2)).curvature(0.3, plane), 0, 1e-15);
  // Helix on a cylinder: u = t, v = a t gives κ = R / (R² + a²).
  const double r = 2.0, a = 0.7;
  const CylinderSurface cyl(kTilted, r, -10, 10);
  const Line2d helix(Vec2(0, 0), Vec2(1, a), 0, 1);
  for (double t : {0.0, 0.5, 3.0}) EXPECT_NEAR(helix.curvature(t, cyl), r / (r * r + a * a), 1e-12);
  // Circle of latitude as a pcurve u = t on the cylinder: κ = 1/R.
  EXPECT_NEAR(Line2d(Vec2(0, 1), Vec2(1, 1)).curvature(0.2, cyl), 1 / r, 1e-12);
}

TEST(Curve3d, LinesAndCircles) {
  const Line3d l(Vec3(1, 1, 1), Vec3(3, 1, 1), 0, 2);
  EXPECT_NEAR(l.length(0, 2), 2, 1e-14);
  EXPECT_NEAR(l.project(Vec3(2.5, 7, -3), 0, 0, 2), 1.5, 1e-14);
  EXPECT_NEAR(l.ParametricCurve3d::project(Vec3(2.5, 7, -3), 0, 0, 2), 1.5, 1e-12);
  EXPECT_EQ(l.curvature(0.5), 0);

  const double r = 1.3;
  const Circle3d c(kTilted, r);
  EXPECT_NEAR(c.length(0, 2 * kPi), 2 * kPi * r, 1e-12);
  for (double t : {0.0, 2.0, 5.0}) {
    EXPECT_NEAR(c.curvature(t), 1 / r, 1e-12);
    EXPECT_NEAR((c.point(t) - kTilted.origin()).norm(), r, 1e-12);
    EXPECT_NEAR(c.d2(t).d1.dot(kTilted.z()), 0, 1e-12);
  }
  const Vec3 off = c.point(2.2) + 0.5 * kTilted.z() + 0.3 * (c.point(2.2) - kTilted.origin());
  EXPECT_NEAR(c.project(off, 2.0, 0, 2 * kPi), 2.2, 1e-12);
  // Metric length with a constant 3D transform.
  const Mat3 m = 2.5 * Mat3::Identity();
  EXPECT_NEAR(c.length(0, 1, [&](const Vec3&) { return m; }), 2.5 * r, 1e-12);
  const auto ts = c.polyline(0, 2 * kPi, 1e-3);
  checkPolyline(ts, 0, 2 * kPi, [&](double t) { return c.point(t); }, 1.1e-3);
}

TEST(Curve3d, CurveOnSurfaceChainRule) {
  const double r = 2.0, a = 0.7;
  auto cyl = std::make_shared<CylinderSurface>(kTilted, r, -10, 10);
  auto pc = std::make_shared<Line2d>(Vec2(0.2, -1), Vec2(1.2, -1 + a), 0, 1);
  const CurveOnSurface3d helix(cyl, pc);
  EXPECT_EQ(helix.tMin(), 0);
  EXPECT_EQ(helix.tMax(), 1);
  const double h = 1e-5;
  for (double t : {0.1, 0.6}) {
    const Curve3dD2 d = helix.d2(t);
    EXPECT_LT((d.d1 - (helix.point(t + h) - helix.point(t - h)) / (2 * h)).norm(), 1e-8);
    EXPECT_LT((d.d2 - (helix.d2(t + h).d1 - helix.d2(t - h).d1) / (2 * h)).norm(), 1e-7);
    EXPECT_NEAR(helix.curvature(t), r / (r * r + a * a), 1e-12);
  }
  EXPECT_NEAR(helix.length(0, 1), std::sqrt(r * r + a * a), 1e-12);
  EXPECT_NEAR(helix.project(helix.point(0.37) + 0.01 * cyl->normal(pc->point(0.37)), 0.5, 0, 1), 0.37, 1e-6);
  const auto copy = helix.clone();
  EXPECT_LT((copy->point(0.3) - helix.point(0.3)).norm(), 1e-15);
}
