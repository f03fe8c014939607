// Projection onto surfaces: the exact analytic overrides and the general Levenberg–Marquardt
// method (called explicitly as ParametricSurface::project), including seams and poles.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "mesher/geometry/CylinderSurface.h"
#include "mesher/geometry/ExpressionSurface.h"
#include "mesher/geometry/PlaneSurface.h"
#include "mesher/geometry/SphereSurface.h"
#include "mesher/geometry/TorusSurface.h"

using namespace aniso;

namespace {

constexpr double kPi = std::numbers::pi;

const Frame kTilted(Vec3(1, -2, 0.5), Vec3(0.3, 0.2, 1.0), Vec3(1, 0.1, 0));

Vec2 general(const ParametricSurface& s, const Vec3& x, const Vec2& start) {
  return s.ParametricSurface::project(x, start);
}

/// Round trips: x = p(uv) + offset·n (offset below the curvature radius), start perturbed.
void roundTrips(const ParametricSurface& s, double vLo, double vHi, double maxOffset, bool exact) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.2, 6.0), V(vLo, vHi), D(-1, 1), P(-0.15, 0.15);
  for (int i = 0; i < 200; ++i) {
    const Vec2 uv(U(rng), V(rng));
    const Vec3 x = s.point(uv) + maxOffset * D(rng) * s.normal(uv);
    const Vec2 start = uv + Vec2(P(rng), P(rng));
    const Vec2 r = exact ? s.project(x, start) : general(s, x, start);
    EXPECT_LT((r - uv).norm(), 1e-8) << "uv " << uv.transpose() << " start " << start.transpose()
                                     << " got " << r.transpose();
  }
}

}  // namespace

TEST(SurfaceProjection, SphereRoundTrips) {
  const SphereSurface sphere(kTilted, 2.0);
  roundTrips(sphere, -1.3, 1.3, 1.0, true);
  roundTrips(sphere, -1.3, 1.3, 1.0, false);
}

TEST(SurfaceProjection, TorusRoundTrips) {
  const TorusSurface torus(kTilted, 3.0, 1.2);
  roundTrips(torus, 0.0, 2 * kPi, 0.6, true);
  roundTrips(torus, 0.0, 2 * kPi, 0.6, false);
}

TEST(SurfaceProjection, CylinderRoundTripsAndClamping) {
  const CylinderSurface cyl(kTilted, 2.5, -3, 3);
  roundTrips(cyl, -2.5, 2.5, 1.5, true);
  roundTrips(cyl, -2.5, 2.5, 1.5, false);
  // Beyond the v range: v is clamped to the domain, by both methods.
  const Vec3 above = kTilted.toWorld(0, 2.5, 5.0);
  for (const Vec2& r : {cyl.project(above, {1.5, 2.9}), general(cyl, above, {1.5, 2.9})}) {
    EXPECT_NEAR(r.x(), kPi / 2, 1e-8);
    EXPECT_DOUBLE_EQ(r.y(), 3.0);
  }
}

TEST(SurfaceProjection, SeamKeepsTheStartSide) {
  const SphereSurface sphere(kTilted, 2.0);
  const Vec3 x = sphere.point({0.01, 0.3});
  // From just below 2π the answer is 2π + 0.01, not 0.01 (left unwrapped near start).
  for (const Vec2& r : {sphere.project(x, {2 * kPi - 0.01, 0.3}), general(sphere, x, {2 * kPi - 0.01, 0.3})}) {
    EXPECT_NEAR(r.x(), 2 * kPi + 0.01, 1e-9);
    EXPECT_NEAR(r.y(), 0.3, 1e-9);
  }
  for (const Vec2& r : {sphere.project(x, {0.05, 0.3}), general(sphere, x, {0.05, 0.3})}) EXPECT_NEAR(r.x(), 0.01, 1e-9);
  const TorusSurface torus(kTilted, 3.0, 1.2);
  const Vec3 y = torus.point({2 * kPi - 0.02, 0.01});
  for (const Vec2& r : {torus.project(y, {0.01, 2 * kPi - 0.01}), general(torus, y, {0.01, 2 * kPi - 0.01})}) {
    EXPECT_NEAR(r.x(), -0.02, 1e-9);
    EXPECT_NEAR(r.y(), 2 * kPi + 0.01, 1e-9);
  }
}

TEST(SurfaceProjection, NearAndAtThePoles) {
  const SphereSurface sphere(kTilted, 2.0);
  // Close to the pole u is ill-conditioned: check the 3D point is reproduced.
  for (double dv : {1e-3, 1e-6}) {
    const Vec3 x = sphere.point({1.0, kPi / 2 - dv});
    for (const Vec2& start : {Vec2(1.5, kPi / 2 - 0.05), Vec2(0.2, kPi / 2), Vec2(3.0, 1.0)}) {
      for (const Vec2& r : {sphere.project(x, start), general(sphere, x, start)}) {
        ASSERT_TRUE(r.allFinite());
        EXPECT_LE(r.y(), kPi / 2);
        EXPECT_LT((sphere.point(r) - x).norm(), 1e-9) << "dv " << dv << " start " << start.transpose();
      }
    }
  }
  // The pole itself, from a start at the pole (pu = 0 there) and away from it.
  const Vec3 pole = kTilted.toWorld(0, 0, 2.0);
  for (const Vec2& start : {Vec2(0.7, kPi / 2), Vec2(0.7, 1.0), Vec2(4.0, -0.5)}) {
    const Vec2 r = general(sphere, pole, start);
    ASSERT_TRUE(r.allFinite());
    EXPECT_NEAR(r.y(), kPi / 2, 1e-7);
    EXPECT_LT((sphere.point(r) - pole).norm(), 1e-9);
    EXPECT_NEAR(sphere.project(pole, start).x(), start.x(), 1e-15) << "u undefined: keep start";
  }
  // Above the pole, off the surface.
  const Vec3 above = kTilted.toWorld(0, 0, 3.0);
  EXPECT_NEAR(general(sphere, above, {2.0, 1.2}).y(), kPi / 2, 1e-7);
}

TEST(SurfaceProjection, PlaneExactAndClamped) {
  const PlaneSurface plane(Vec3(1, 1, 1), Vec3(2, 0, 0), Vec3(1, 1, 0), -1, 1, -1, 1);
  const Vec3 x = plane.point({0.3, -0.4}) + Vec3(0, 0, 5);
  for (const Vec2& r : {plane.project(x, {0, 0}), general(plane, x, {0, 0})}) EXPECT_LT((r - Vec2(0.3, -0.4)).norm(), 1e-12);
  const Vec3 outside = plane.point({3, 0.5});
  for (const Vec2& r : {plane.project(outside, {0, 0}), general(plane, outside, {0, 0})}) {
    EXPECT_NEAR(r.x(), 1, 1e-12);
    EXPECT_LE(r.y(), 1);
  }
}

TEST(SurfaceProjection, ExpressionSurfaceRoundTrips) {
  const ExpressionSurface surf0("u", "v", "1.5*exp(-0.001*(u^2+v^2))*sin(2*u)*cos(0.2*v)",
                                SurfaceDomain{-6, 6, -6, 6});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-5.5, 5.5), P(-0.2, 0.2), D(-0.1, 0.1);
  for (int i = 0; i < 100; ++i) {
    const Vec2 uv(U(rng), U(rng));
    const Vec3 x = surf0.point(uv) + D(rng) * surf0.normal(uv);
    const Vec2 r = surf0.project(x, uv + Vec2(P(rng), P(rng)));
    EXPECT_LT((r - uv).norm(), 1e-7) << uv.transpose();
  }
}

TEST(SurfaceProjection, NeverThrowsOnBadInput) {
  const SphereSurface sphere(kTilted, 2.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NO_THROW({
    const Vec2 r = general(sphere, Vec3(nan, 0, 0), {1, 0.2});
    EXPECT_TRUE(r.allFinite());
    const Vec2 q = general(sphere, Vec3(1, 2, 3), {nan, 0.2});
    EXPECT_TRUE(q.allFinite());
    const Vec2 c = sphere.project(kTilted.origin(), {1, 0.2});  // the centre: any point is nearest
    EXPECT_TRUE(c.allFinite());
  });
}
