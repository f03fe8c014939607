// Tests of the robust curvature sizing (mesher/metric/RobustCurvature.h) and of the element
// budget (mesher/sizing/ElementBudget.h, FaceSizePrediction.h).
#include <gtest/gtest.h>

#include <cmath>

#include "mesher/control/CSAnalytic2d.h"
#include "mesher/control/CSQuadtree2d.h"
#include "mesher/geometry/CylinderSurface.h"
#include "mesher/geometry/ExpressionSurface.h"
#include "mesher/metric/RobustCurvature.h"
#include "mesher/metric/SurfaceCurvatureMetric.h"
#include "mesher/sizing/ElementBudget.h"

using namespace aniso;

namespace {

CurvatureSizing sizing(double hMin, double hMax) {
  CurvatureSizing s;
  s.curvatureRatio = 0.15;
  s.hMin = hMin;
  s.hMax = hMax;
  s.anisotropy = 1;
  s.contourAnisotropy = 1;
  return s;
}

double smallest(const Metric2d& m) { return m.angleLengths().h1; }

/// The unit square, flat but for a bump of height a and width w at (0.5, 0.5).
ExpressionSurface bump(double a, double w) {
  const std::string z = std::to_string(a) + "*exp(-((u-0.5)^2+(v-0.5)^2)/" + std::to_string(w * w) + ")";
  return ExpressionSurface("u", "v", z, SurfaceDomain{0, 1, 0, 1});
}

}  // namespace

// A spike narrower than the size it asks for: point curvature 2a/w² = 2 asks for 0.075
// (7.5 times the bump's width), the surface deviates by 1e-4 over that distance: ignored.
TEST(RobustCurvature, SpikeNarrowerThanItsSizeIsIgnored) {
  const ExpressionSurface s = bump(1e-4, 1e-2);
  const CurvatureSizing cs = sizing(1e-4, 0.5);
  const Box2 box(Vec2(0, 0), Vec2(1, 1));
  const RobustCurvatureBounds rb = RobustCurvatureBounds::of(box, cs, 0.0, 0.0);
  const Vec2 top(0.5, 0.5);
  const double point = smallest(surfaceCurvatureSizing(s, top, 1e-8, cs));
  EXPECT_NEAR(point, 0.075, 0.01);
  EXPECT_GT(smallest(robustCurvatureSizing(s, top, 1e-8, cs, rb)), 0.9 * cs.hMax);
}

// A bump as high as it is wide is a real feature: its curvature is kept.
TEST(RobustCurvature, TallBumpIsKept) {
  const ExpressionSurface s = bump(0.05, 0.05);
  const CurvatureSizing cs = sizing(1e-4, 0.5);
  const Box2 box(Vec2(0, 0), Vec2(1, 1));
  const RobustCurvatureBounds rb = RobustCurvatureBounds::of(box, cs, 0.0, 0.0);
  const Vec2 top(0.5, 0.5);
  const double point = smallest(surfaceCurvatureSizing(s, top, 1e-8, cs));
  EXPECT_LT(point, 0.005);
  EXPECT_NEAR(smallest(robustCurvatureSizing(s, top, 1e-8, cs, rb)), point, 0.1 * point);
}

// On a cylinder (a fillet, a hole) the secant curvature is exactly 1/R: nothing changes,
// also at the corners of the face's (u, v) box.
TEST(RobustCurvature, CylinderUnchangedEverywhere) {
  const CylinderSurface s(Frame(Vec3::Zero(), Vec3::UnitZ()), 2.0, 0.0, 10.0);
  const CurvatureSizing cs = sizing(1e-4, 5.0);
  const Box2 box(Vec2(0, 0), Vec2(1.5, 10));
  const RobustCurvatureBounds rb = RobustCurvatureBounds::of(box, cs, 1e-7, 3.0);
  for (const Vec2 uv : {Vec2(0.7, 5), Vec2(0, 0), Vec2(1.5, 10), Vec2(0, 10)}) {
    const double point = smallest(surfaceCurvatureSizing(s, uv, 1e-8, cs));
    EXPECT_NEAR(point, 0.3, 1e-9);
    EXPECT_NEAR(smallest(robustCurvatureSizing(s, uv, 1e-8, cs, rb)), point, 1e-6) << uv.transpose();
  }
}

// The floor: never below 10 CAD tolerances nor γ_c times 0.5 % of the face's width.
TEST(RobustCurvature, FloorFromToleranceAndWidth) {
  const CurvatureSizing cs = sizing(1e-4, 5.0);
  const Box2 box(Vec2(0, 0), Vec2(1, 1));
  EXPECT_DOUBLE_EQ(RobustCurvatureBounds::of(box, cs, 0.01, 1.0).floor, kToleranceFactor * 0.01);
  EXPECT_DOUBLE_EQ(RobustCurvatureBounds::of(box, cs, 1e-7, 2000.0).floor, cs.curvatureRatio * kMinRadiusFraction * 2000.0);
  EXPECT_DOUBLE_EQ(RobustCurvatureBounds::of(box, cs, 1e-7, 1e-3).floor, cs.hMin);
  const CylinderSurface s(Frame(Vec3::Zero(), Vec3::UnitZ()), 2.0, 0.0, 10.0);
  const RobustCurvatureBounds rb = RobustCurvatureBounds::of(Box2(Vec2(0, 0), Vec2(6, 10)), cs, 0.1, 1.0);
  EXPECT_NEAR(smallest(robustCurvatureSizing(s, Vec2(1, 5), 1e-8, cs, rb)), 1.0, 1e-9);  // 0.3 raised to 10 × 0.1
}

// Prediction of a uniform face and the budget's floor.
TEST(ElementBudget, PredictionAndFloor) {
  SizingParameters p;
  const Box2 box(Vec2(0, 0), Vec2(10, 10));
  CSQuadtree2d cs(box, p);
  cs.setContinuousSource(CSAnalytic2d(box, [](const Vec2& uv) { return Metric2d::isotropic(uv.x() < 5 ? 0.1 : 1.0); }));
  FaceBoundary b;
  b.loops.push_back({{Vec2(0, 0)}, {Vec2(10, 0)}, {Vec2(10, 10)}, {Vec2(0, 10)}});
  const FaceSizePrediction pred(cs, b);
  const double ideal = 50 / (0.01 * std::sqrt(3.0) / 4) + 50 / (std::sqrt(3.0) / 4);  // ~11,660
  EXPECT_NEAR(pred.triangles(), ideal, 0.15 * ideal);
  EXPECT_NEAR(pred.triangles(1.0), 100 / (std::sqrt(3.0) / 4), 1.0);

  const std::vector<const FaceSizePrediction*> faces{&pred};
  const ElementBudget fits = decideBudget(faces, {}, 1e6, 1.0);
  EXPECT_TRUE(fits.fits);
  EXPECT_EQ(fits.floor, 0.0);
  const ElementBudget coarse = decideBudget(faces, {}, 1000, 1.0);
  EXPECT_TRUE(coarse.fits);
  EXPECT_GT(coarse.floor, 0.1);
  EXPECT_LE(coarse.predictedAfter, 1000);
  EXPECT_GT(coarse.predictedAfter, 900);
  ASSERT_EQ(coarse.coarsened.size(), 1u);
  EXPECT_EQ(coarse.coarsened[0].face, 0);
  const ElementBudget refused = decideBudget(faces, {}, 100, 1.0);
  EXPECT_FALSE(refused.fits);
  // tets of one solid with this face: 0.1 T^1.5
  const ElementBudget volume = decideBudget(faces, {{0}}, 0, 1.0);
  EXPECT_NEAR(volume.tets, kTetsPerTriangle32 * std::pow(volume.triangles, 1.5), 1e-6 * volume.tets);

  // with its volume: a 10 x 10 plate 0.1 thick (two such faces) has about as many tets as
  // triangles, not T^1.5; a cube of side 10 (six) keeps the T^1.5 estimate within 10 %
  EXPECT_NEAR(pred.area(), 100.0, 1e-6);
  const ElementBudget plate = decideBudget({&pred, &pred}, {{0, 1}}, 0, 1.0, {10.0});
  EXPECT_NEAR(plate.tets, plate.triangles, 1e-6 * plate.tets);
  EXPECT_LT(plate.tets, 0.1 * kTetsPerTriangle32 * std::pow(plate.triangles, 1.5));
  const FaceSizePrediction* six[] = {&pred, &pred, &pred, &pred, &pred, &pred};
  const std::vector<const FaceSizePrediction*> cube(std::begin(six), std::end(six));
  const ElementBudget uniform = decideBudget(cube, {{0, 1, 2, 3, 4, 5}}, 0, 1.0, {1000.0});
  const ElementBudget unknown = decideBudget(cube, {{0, 1, 2, 3, 4, 5}}, 0, 1.0);
  EXPECT_LE(uniform.tets, unknown.tets);
  // the face is graded (0.1 and 1): its mean size is below the large side, so the volume
  // bound stays above the T^1.5 estimate's half at least
  EXPECT_GT(uniform.tets, 0.5 * unknown.tets);

  EXPECT_EQ(applySizeFloor(cs, 0.5) > 0, true);
  EXPECT_NEAR(FaceSizePrediction(cs, b).triangles(), pred.triangles(0.5), 0.15 * pred.triangles(0.5));
}
