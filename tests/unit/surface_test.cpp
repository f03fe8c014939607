// Analytic surfaces and the general ParametricSurface methods against analytic truth.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/geometry/CylinderSurface.h"
#include "mesher/geometry/ExpressionSurface.h"
#include "mesher/geometry/PlaneSurface.h"
#include "mesher/geometry/SphereSurface.h"
#include "mesher/geometry/TorusSurface.h"

using namespace aniso;

namespace {

constexpr double kPi = std::numbers::pi;

const Frame kTilted(Vec3(1, -2, 0.5), Vec3(0.3, 0.2, 1.0), Vec3(1, 0.1, 0));

void expectNear(const Vec3& a, const Vec3& b, double tol, const char* what) {
  EXPECT_LT((a - b).norm(), tol) << what << ": " << a.transpose() << " vs " << b.transpose();
}

/// d1, d2 against central differences of point() and d1().
void checkDerivatives(const ParametricSurface& s, const std::vector<Vec2>& pts, double scale) {
  const double h = 1e-5;
  for (const Vec2& uv : pts) {
    const SurfaceD2 d = s.d2(uv);
    const SurfaceD1 e = s.d1(uv);
    const Vec2 du(h, 0), dv(0, h);
    expectNear(d.p, s.point(uv), 1e-12 * scale, "p");
    expectNear(e.p, s.point(uv), 1e-12 * scale, "p(d1)");
    expectNear(e.pu, d.pu, 1e-12 * scale, "pu(d1) vs pu(d2)");
    expectNear(d.pu, (s.point(uv + du) - s.point(uv - du)) / (2 * h), 1e-6 * scale, "pu");
    expectNear(d.pv, (s.point(uv + dv) - s.point(uv - dv)) / (2 * h), 1e-6 * scale, "pv");
    expectNear(d.puu, (s.d1(uv + du).pu - s.d1(uv - du).pu) / (2 * h), 1e-5 * scale, "puu");
    expectNear(d.pvv, (s.d1(uv + dv).pv - s.d1(uv - dv).pv) / (2 * h), 1e-5 * scale, "pvv");
    expectNear(d.puv, (s.d1(uv + dv).pu - s.d1(uv - dv).pu) / (2 * h), 1e-5 * scale, "puv (pu_v)");
    expectNear(d.puv, (s.d1(uv + du).pv - s.d1(uv - du).pv) / (2 * h), 1e-5 * scale, "puv (pv_u)");
  }
}

const std::vector<Vec2> kSamples = {{0.1, 0.2}, {1.3, -0.7}, {2.9, 1.1}, {4.4, 0.05}, {6.0, -1.4}};

}  // namespace

TEST(Surface, DerivativesMatchFiniteDifferences) {
  checkDerivatives(PlaneSurface(Vec3(1, 2, 3), Vec3(2, 0, 0.5), Vec3(0.3, 1, 0), -5, 5, -5, 5), kSamples, 3);
  checkDerivatives(CylinderSurface(kTilted, 2.5, -3, 3), kSamples, 2.5);
  checkDerivatives(SphereSurface(kTilted, 1.7), kSamples, 1.7);
  checkDerivatives(TorusSurface(kTilted, 3, 1.2), kSamples, 4.2);
  SurfaceDomain dom{-6, 6, -6, 6};
  checkDerivatives(ExpressionSurface("u", "v", "1.5*exp(-0.001*(u^2+v^2))*sin(2*u)*cos(0.2*v)", dom), kSamples, 3);
}

TEST(Surface, AnalyticPointsLieOnTheirShapes) {
  const SphereSurface sphere(kTilted, 1.7);
  const TorusSurface torus(kTilted, 3, 1.2);
  const CylinderSurface cyl(kTilted, 2.5, -3, 3);
  for (const Vec2& uv : kSamples) {
    EXPECT_NEAR((sphere.point(uv) - kTilted.origin()).norm(), 1.7, 1e-12);
    const Vec3 l = kTilted.toLocal(cyl.point(uv));
    EXPECT_NEAR(std::hypot(l.x(), l.y()), 2.5, 1e-12);
    EXPECT_NEAR(l.z(), uv.y(), 1e-12);
    const Vec3 t = kTilted.toLocal(torus.point(uv));
    EXPECT_NEAR(std::hypot(std::hypot(t.x(), t.y()) - 3, t.z()), 1.2, 1e-12);
  }
  // OCCT conventions: u = v = 0 lies on the frame's x axis, v = π/2 is the north pole.
  expectNear(sphere.point({0, 0}), kTilted.toWorld(1.7, 0, 0), 1e-12, "sphere (0,0)");
  expectNear(sphere.point({0.7, kPi / 2}), kTilted.toWorld(0, 0, 1.7), 1e-12, "north pole");
  expectNear(torus.point({0, 0}), kTilted.toWorld(4.2, 0, 0), 1e-12, "torus outer");
  expectNear(torus.point({0, kPi}), kTilted.toWorld(1.8, 0, 0), 1e-12, "torus inner");
}

TEST(Surface, NormalsIncludingSingularPoints) {
  const SphereSurface sphere(kTilted, 2.0);
  for (const Vec2& uv : kSamples) {
    const Vec3 radial = (sphere.point(uv) - kTilted.origin()).normalized();
    expectNear(sphere.normal(uv), radial, 1e-12, "sphere normal");
    expectNear(sphere.ParametricSurface::normal(uv), radial, 1e-10, "general normal");
  }
  // At the poles pu = 0: the general method must fall back to a nearby regular point.
  for (double u : {0.0, 1.0, 4.0}) {
    const Vec3 n = sphere.ParametricSurface::normal({u, kPi / 2});
    ASSERT_TRUE(n.allFinite());
    expectNear(n, kTilted.z(), 1e-4, "north pole normal");
    expectNear(sphere.ParametricSurface::normal({u, -kPi / 2}), -kTilted.z(), 1e-4, "south pole normal");
  }
  const PlaneSurface plane(Vec3::Zero(), Vec3(2, 0, 0), Vec3(1, 1, 0), 0, 1, 0, 1);
  expectNear(plane.normal({0.3, 0.3}), Vec3::UnitZ(), 1e-15, "plane normal");
}

TEST(Surface, FundamentalFormsOfSphere) {
  const double r = 2.0;
  const SphereSurface sphere(kTilted, r);
  const Vec2 uv(0.4, 0.6);
  const Mat2 g = sphere.firstFundamentalForm(uv);
  EXPECT_NEAR(g(0, 0), r * r * std::cos(0.6) * std::cos(0.6), 1e-12);
  EXPECT_NEAR(g(0, 1), 0, 1e-12);
  EXPECT_NEAR(g(1, 1), r * r, 1e-12);
  // Outward normal: B = −G / r.
  const Mat2 b = sphere.secondFundamentalForm(uv);
  EXPECT_LT((b + g / r).norm(), 1e-12);
}

TEST(Surface, SphereCurvatureIsUmbilic) {
  const double r = 2.0;
  const SphereSurface sphere(kTilted, r);
  for (const Vec2& uv : {Vec2(0.4, 0.6), Vec2(3.0, -1.2), Vec2(1.0, kPi / 2 - 1e-3), Vec2(1.0, kPi / 2)}) {
    const PrincipalCurvatures pc = sphere.curvature(uv);
    EXPECT_NEAR(pc.k1, -1 / r, 1e-6);
    EXPECT_NEAR(pc.k2, -1 / r, 1e-6);
    EXPECT_NEAR(pc.maxAbs(), 1 / r, 1e-6);
    EXPECT_TRUE(pc.d3_1.allFinite() && pc.d3_2.allFinite());
    EXPECT_NEAR(pc.d3_1.dot(pc.d3_2), 0, 1e-6) << "G-orthogonal directions";
  }
  const PrincipalCurvatures pc = sphere.curvature({0.4, 0.6});
  EXPECT_NEAR(std::abs(pc.dir1.x()), 1, 1e-12) << "umbilic: dir1 is the u direction";
}

TEST(Surface, CylinderCurvature) {
  const double r = 2.5;
  const CylinderSurface cyl(kTilted, r, -3, 3);
  for (const Vec2& uv : kSamples) {
    const PrincipalCurvatures pc = cyl.curvature(uv);
    EXPECT_NEAR(pc.k1, -1 / r, 1e-12);
    EXPECT_NEAR(pc.k2, 0, 1e-12);
    EXPECT_NEAR(std::abs(pc.dir1.x()), 1, 1e-9) << "k1 along the circle";
    EXPECT_NEAR(std::abs(pc.dir2.y()), 1, 1e-9) << "k2 along the axis";
    EXPECT_NEAR(std::abs(pc.d3_2.dot(kTilted.z())), 1, 1e-9);
  }
}

TEST(Surface, TorusCurvature) {
  const double big = 3, small = 1.2;
  const TorusSurface torus(kTilted, big, small);
  // Outer equator (v = 0): −1/r across the tube, −1/(R+r) around the axis.
  PrincipalCurvatures pc = torus.curvature({0.7, 0.0});
  EXPECT_NEAR(pc.k1, -1 / small, 1e-12);
  EXPECT_NEAR(pc.k2, -1 / (big + small), 1e-12);
  EXPECT_NEAR(std::abs(pc.dir1.y()), 1, 1e-9);
  // Inner equator (v = π): −1/r, +1/(R−r) (saddle, negative Gaussian curvature).
  pc = torus.curvature({2.0, kPi});
  EXPECT_NEAR(pc.k1, -1 / small, 1e-12);
  EXPECT_NEAR(pc.k2, 1 / (big - small), 1e-12);
  // Anywhere: −1/r and −cos v/(R + r cos v).
  for (const Vec2& uv : kSamples) {
    pc = torus.curvature(uv);
    const double kc = -1 / small, ku = -std::cos(uv.y()) / (big + small * std::cos(uv.y()));
    EXPECT_NEAR(pc.k1, std::min(kc, ku), 1e-10);
    EXPECT_NEAR(pc.k2, std::max(kc, ku), 1e-10);
    EXPECT_NEAR(pc.d3_1.dot(pc.d3_2), 0, 1e-9);
  }
}

TEST(Surface, UmbilicDirectionsAreGOrthogonal) {
  // A plane with skew axes: k1 = k2 = 0, dir1 = u, dir2 G-orthogonal to it.
  const PlaneSurface skew(Vec3::Zero(), Vec3(2, 0, 0), Vec3(1, 1, 0.5), 0, 1, 0, 1);
  const PrincipalCurvatures pc = skew.curvature({0.5, 0.5});
  EXPECT_EQ(pc.k1, 0);
  EXPECT_EQ(pc.k2, 0);
  EXPECT_NEAR(pc.dir1.x(), 1, 1e-15);
  EXPECT_NEAR(pc.dir1.dot(skew.firstFundamentalForm({0.5, 0.5}) * pc.dir2), 0, 1e-12);
  EXPECT_NEAR(pc.d3_1.dot(pc.d3_2), 0, 1e-12);
  EXPECT_NEAR(pc.dir2.norm(), 1, 1e-15);
}

TEST(Surface, SaddleCurvatureDirections) {
  // z = u v: at the origin k = ±1 along the diagonals.
  const ExpressionSurface saddle("u", "v", "u*v", SurfaceDomain{-1, 1, -1, 1});
  const PrincipalCurvatures pc = saddle.curvature({0, 0});
  EXPECT_NEAR(pc.k1, -1, 1e-7);
  EXPECT_NEAR(pc.k2, 1, 1e-7);
  EXPECT_NEAR(std::abs(pc.dir1.x()), std::sqrt(0.5), 1e-7);
  EXPECT_NEAR(pc.dir1.x() * pc.dir1.y(), -0.5, 1e-7) << "k = −1 along (1, −1)";
  EXPECT_NEAR(pc.dir2.x() * pc.dir2.y(), 0.5, 1e-7) << "k = +1 along (1, 1)";
}

TEST(Surface, ParameterizationTensorOfSphere) {
  const double r = 2.0;
  const SphereSurface sphere(kTilted, r);
  const Vec2 uv(0.4, 0.6);
  const Mat2 m = sphere.parameterizationTensor(uv, 1e-8);
  EXPECT_LT((m - m.transpose()).norm(), 1e-14);
  EXPECT_LT((m * m - sphere.firstFundamentalForm(uv)).norm(), 1e-12);
  // At the pole g11 = 0: the guard raises it to gMin and keeps M_p SPD.
  const double gMin = 1e-4 * r * r;
  const Mat2 mp = sphere.parameterizationTensor({1.0, kPi / 2}, gMin);
  EXPECT_LT((mp - mp.transpose()).norm(), 1e-14);
  const Eigen::SelfAdjointEigenSolver<Mat2> es(mp);
  EXPECT_GT(es.eigenvalues().minCoeff(), 0);
  Mat2 guarded;
  guarded << gMin, 0, 0, r * r;
  EXPECT_LT((mp * mp - guarded).norm(), 1e-12);
  // With gMin = 0 the result is still SPD (tiny floor) and finite.
  const Mat2 m0 = sphere.parameterizationTensor({1.0, kPi / 2}, 0);
  EXPECT_TRUE(m0.allFinite());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat2>(m0).eigenvalues().minCoeff(), 0);
}

TEST(Surface, ParameterizationTensorOfPlane) {
  const PlaneSurface scaled(Vec3::Zero(), Vec3(2, 0, 0), Vec3(0, 1, 0), 0, 1, 0, 1);
  Mat2 expected;
  expected << 2, 0, 0, 1;
  EXPECT_LT((scaled.parameterizationTensor({0.5, 0.5}, 0) - expected).norm(), 1e-14);
  const PlaneSurface skew(Vec3::Zero(), Vec3(2, 0, 0), Vec3(1, 1, 0.5), 0, 1, 0, 1);
  const Mat2 m = skew.parameterizationTensor({0.5, 0.5}, 0);
  EXPECT_LT((m - m.transpose()).norm(), 1e-14);
  EXPECT_LT((m * m - skew.firstFundamentalForm({0.5, 0.5})).norm(), 1e-12);
  // Lengths: |M_p Δuv| equals the 3D length of a segment on a plane.
  const Vec2 duv(0.3, -0.2);
  EXPECT_NEAR((m * duv).norm(), (skew.point(Vec2(0.5, 0.5) + duv) - skew.point({0.5, 0.5})).norm(), 1e-12);
}
