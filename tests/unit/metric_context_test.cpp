// Tests of MetricContext2d/3d and the vertex cache of metric-space coordinates
// (sec. 3.2.4, sec. 6.4.1).
#include <gtest/gtest.h>

#include <set>

#include "mesher/metric/MetricContext.h"

using namespace aniso;

TEST(MetricContext, CounterChangesAtEverySet) {
  MetricContext2d mc;
  const auto c0 = mc.counter();
  EXPECT_NE(c0, 0u);
  mc.set(Metric2d::isotropic(0.5));
  const auto c1 = mc.counter();
  EXPECT_GT(c1, c0);
  mc.set(Metric2d::isotropic(0.5));  // same metric: still a new counter (thesis: every update)
  EXPECT_GT(mc.counter(), c1);
}

TEST(MetricContext, HoldsSurfaceTransformation) {
  MetricContext2d mc;
  Mat2 mp;
  mp << 2.0, 0.3, 0.3, 1.0;
  const Metric2d ms = Metric2d::fromAngle(0.4, 0.1, 0.5);
  mc.set(ms, mp);
  EXPECT_LT((mc.transformation() - ms.matrix() * mp).norm(), 1e-15);  // eq. 2.9
  const Vec2 p(0.3, -0.7), q(1.0, 0.2);
  EXPECT_LT((mc.toMetricSpace(p) - ms.matrix() * (mp * p)).norm(), 1e-14);
  EXPECT_LT((mc.toRealSpace(p) - mp * p).norm(), 1e-15);
  EXPECT_NEAR(mc.metricDistance(p, q), ms.length(mp * (q - p)), 1e-14);
  EXPECT_NEAR(mc.realDistance(p, q), (mp * (q - p)).norm(), 1e-15);
  EXPECT_EQ(mc.sizing().matrix(), ms.matrix());
  EXPECT_EQ(mc.parameterization(), mp);
}

TEST(MetricContext, CacheIsReusedUntilTheMetricChanges) {
  MetricContext2d mc;
  mc.set(Metric2d::isotropic(0.5));
  MetricCoords2d cache;
  EXPECT_EQ(cache.counter, 0u);
  const Vec2 x(1, 2);
  EXPECT_EQ(metricCoordinates(mc, x, cache), Vec2(2, 4));
  EXPECT_EQ(cache.counter, mc.counter());
  // Valid cache: the stored value is returned, even for another x (proves no recompute).
  EXPECT_EQ(metricCoordinates(mc, Vec2(100, 100), cache), Vec2(2, 4));
  // New metric: recomputed.
  mc.set(Metric2d::isotropic(0.25));
  EXPECT_EQ(metricCoordinates(mc, x, cache), Vec2(4, 8));
  // Vertex moved: invalidate, then recomputed with the same metric.
  cache.invalidate();
  EXPECT_EQ(metricCoordinates(mc, Vec2(1, 0), cache), Vec2(4, 0));
}

TEST(MetricContext, CountersAreUniqueAcrossContextsAndCopies) {
  MetricContext2d a, b;
  EXPECT_NE(a.counter(), b.counter());
  a.set(Metric2d::isotropic(1.0));
  b.set(Metric2d::isotropic(2.0));
  MetricCoords2d cache;
  metricCoordinates(a, Vec2(1, 1), cache);
  // A cache filled through a is not valid for b.
  EXPECT_EQ(metricCoordinates(b, Vec2(1, 1), cache), Vec2(0.5, 0.5));

  MetricContext2d c = a;  // same metric, same counter: caches stay valid
  EXPECT_EQ(c.counter(), a.counter());
  std::set<std::uint64_t> seen;
  for (int i = 0; i < 100; ++i) {
    a.set(Metric2d::isotropic(1.0 + i));
    c.set(Metric2d::isotropic(1.0 + i));
    b = a;  // assignment too
    b.set(Metric2d::isotropic(3.0));
    EXPECT_TRUE(seen.insert(a.counter()).second);
    EXPECT_TRUE(seen.insert(c.counter()).second);
    EXPECT_TRUE(seen.insert(b.counter()).second);
  }
}

TEST(MetricContext, ProximityCheck) {
  MetricContext2d mc;
  mc.set(Metric2d::isotropic(0.1));
  EXPECT_FALSE(mc.covers(Vec2(0, 0), 1.0));  // no anchor
  mc.setAt(Vec2(1, 1), Metric2d::isotropic(0.1), Mat2::Identity());
  EXPECT_TRUE(mc.covers(Vec2(1.05, 1), 0.6));   // 0.5 in metric
  EXPECT_FALSE(mc.covers(Vec2(1.1, 1), 0.6));   // 1.0 in metric
  mc.set(Metric2d::isotropic(0.1));
  EXPECT_FALSE(mc.covers(Vec2(1, 1), 0.6));  // plain set forgets the anchor
}

TEST(MetricContext, ThreeDimensional) {
  MetricContext3d mc;
  const auto c0 = mc.counter();
  const Metric3d m = Metric3d::fromDirections(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), 0.5, 1.0, 2.0);
  mc.set(m);
  EXPECT_NE(mc.counter(), c0);
  MetricCoords3d cache;
  EXPECT_EQ(metricCoordinates(mc, Vec3(1, 1, 1), cache), Vec3(2, 1, 0.5));  // eq. 2.17
  EXPECT_EQ(metricCoordinates(mc, Vec3(9, 9, 9), cache), Vec3(2, 1, 0.5));  // cached
  mc.setAt(Vec3::Zero(), Metric3d::isotropic(1.0));
  EXPECT_EQ(metricCoordinates(mc, Vec3(9, 9, 9), cache), Vec3(9, 9, 9));
  EXPECT_TRUE(mc.covers(Vec3(0.5, 0, 0), 0.6));
  EXPECT_NEAR(mc.metricDistance(Vec3::Zero(), Vec3(3, 4, 0)), 5.0, 1e-15);
}
