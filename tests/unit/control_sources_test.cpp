// General-level ACS operations (sec. 3.2.2, 3.2.3): extended metric sources in 2D and 3D
// and superposition of control spaces.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "mesher/control/CSAnalytic2d.h"
#include "mesher/control/CSAnalytic3d.h"
#include "mesher/control/CSOctree3d.h"
#include "mesher/control/CSQuadtree2d.h"
#include "mesher/core/Error.h"
#include "mesher/geometry/Circle2d.h"
#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricIntersection.h"
#include "control_fixtures.h"

using namespace aniso;
using namespace aniso::testing;

namespace {

CSQuadtree2d uniformQuadtree(double h) {
  CSQuadtree2d cs(kSquare, SizingParameters{});
  cs.setContinuousSource(CSAnalytic2d(kSquare, [h](const Vec2&) { return Metric2d::isotropic(h); }));
  return cs;
}

/// |M_fine u| ≥ |M_coarse u| for sampled u: `fine` requests at most the lengths of `coarse`.
bool atMost2d(const Metric2d& fine, const Metric2d& coarse) {
  for (int i = 0; i < 36; ++i) {
    const Vec2 u(std::cos(kPi * i / 36), std::sin(kPi * i / 36));
    if (fine.length(u) < coarse.length(u) * (1 - 1e-9)) return false;
  }
  return true;
}

bool atMost3d(const Metric3d& fine, const Metric3d& coarse) {
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      const double t = kPi * i / 12, p = kPi * j / 6;
      const Vec3 u(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
      if (fine.length(u) < coarse.length(u) * (1 - 1e-9)) return false;
    }
  return true;
}

double segmentDistance(const Vec2& x, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t = std::clamp((x - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (x - (a + t * d)).norm();
}

}  // namespace

TEST(ControlSources, SegmentWithRadiusGivesSmallElementsNearItAndDefaultFarAway) {
  CSQuadtree2d cs = uniformQuadtree(0.1);
  const Vec2 a(0.2, 0.2), b(0.8, 0.7);
  const double r = 0.05, h = 0.005;
  cs.insertExtendedSource(SegmentSource2d(a, b, r), Metric2d::isotropic(h));
  cs.validate();
  for (double t = 0; t <= 1; t += 0.01) {
    const Vec2 p = a + t * (b - a);
    const Vec2 off = p + 0.5 * r * Vec2(-(b - a).y(), (b - a).x()).normalized();
    EXPECT_LE(cs.getMetric(p).sizing.lengthAlong(Vec2(1, 0)), h * (1 + 1e-9)) << p.transpose();
    EXPECT_LE(cs.getMetric(off).sizing.lengthAlong(Vec2(0, 1)), h * (1 + 1e-9)) << off.transpose();
  }
  EXPECT_NEAR(cs.getMetric(Vec2(0.9, 0.1)).sizing.lengthAlong(Vec2(1, 0)), 0.1, 1e-9);
  int inside = 0;
  cs.forEachControlVertex([&](const Vec2& p, const Metric2d& m) {
    const double d = segmentDistance(p, a, b);
    if (d <= r) {
      ++inside;
      EXPECT_LE(m.lengthAlong(Vec2(1, 0)), h * (1 + 1e-9));
    } else if (d > r + 4 * h * 2) {
      EXPECT_NEAR(m.lengthAlong(Vec2(1, 0)), 0.1, 1e-9) << p.transpose();
    }
  });
  EXPECT_GT(inside, 100);
}

TEST(ControlSources, PointAndCurveSourcesIn2d) {
  CSQuadtree2d cs = uniformQuadtree(0.1);
  const Metric2d along = Metric2d::fromAngle(0, 0.004, 0.02);
  cs.insertExtendedSource(PointSource2d(Vec2(0.25, 0.75), 0.08), along);
  auto circle = std::make_shared<Circle2d>(Vec2(0.6, 0.4), 0.25);
  cs.insertExtendedSource(CurveSource2d(circle, 0, kPi, 0.02), Metric2d::isotropic(0.003));
  cs.validate();
  int checked = 0;
  cs.forEachControlVertex([&](const Vec2& p, const Metric2d& m) {
    if ((p - Vec2(0.25, 0.75)).norm() <= 0.08) {
      EXPECT_TRUE(atMost2d(m, along)) << p.transpose();
      ++checked;
    }
    if (std::abs((p - Vec2(0.6, 0.4)).norm() - 0.25) <= 0.02 && p.y() >= 0.4 + 1e-9) {
      EXPECT_LE(m.lengthAlong(Vec2(1, 1)), 0.003 * (1 + 1e-9)) << p.transpose();
      ++checked;
    }
  });
  EXPECT_GT(checked, 100);
  for (double t = 0.05; t < kPi; t += 0.1)
    EXPECT_LE(cs.getMetric(circle->point(t)).sizing.lengthAlong(Vec2(0, 1)), 0.003 * (1 + 1e-9));
  // The lower half of the circle (t ∈ (π, 2π)) is not part of the source.
  EXPECT_GT(cs.getMetric(circle->point(1.5 * kPi)).sizing.lengthAlong(Vec2(0, 1)), 0.05);
}

TEST(ControlSources, SamplePointsAreAtMostOneMetricUnitApart) {
  const Metric2d m = Metric2d::fromAngle(0.4, 0.01, 0.05);
  const MetricLength2d len = [&m](const Vec2&, const Vec2& v) { return m.length(v); };
  const SegmentSource2d seg(Vec2(0, 0), Vec2(1, 0.3), 0);
  const std::vector<Vec2> pts = seg.samplePoints(len);
  const double total = m.length(Vec2(1, 0.3));
  EXPECT_EQ(pts.size(), std::size_t(std::ceil(total)) + 1);
  for (std::size_t i = 1; i < pts.size(); ++i) EXPECT_LE(m.length(pts[i] - pts[i - 1]), 1 + 1e-9);
  EXPECT_THROW(SegmentSource2d(Vec2(0, 0), Vec2(1, 0), -1), InputError);
}

TEST(ControlSources, ExtendedSourcesBeforeInitializationAreAppliedAtInitialization) {
  CSQuadtree2d cs(kSquare, SizingParameters{});
  cs.insertExtendedSource(PointSource2d(Vec2(0.3, 0.3), 0.1), Metric2d::isotropic(0.01));
  cs.insertExtendedSource(SegmentSource2d(Vec2(0.6, 0.9), Vec2(0.9, 0.6), 0.0), Metric2d::isotropic(0.05));
  EXPECT_FALSE(cs.initialized());
  EXPECT_GT(cs.pendingSourceCount(), 10u);
  cs.initializeControlVertices();
  cs.validate();
  cs.forEachControlVertex([](const Vec2& p, const Metric2d& m) {
    if ((p - Vec2(0.3, 0.3)).norm() <= 0.1) {
      EXPECT_LE(m.lengthAlong(Vec2(1, 0)), 0.01 * (1 + 1e-9));
    }
  });
  EXPECT_LE(cs.getMetric(Vec2(0.75, 0.75)).sizing.lengthAlong(Vec2(1, 0)), 0.05 * (1 + 1e-9));
}

TEST(ControlSources, ExtendedSourcesIn3d) {
  CSOctree3d cs(kCube, SizingParameters{});
  cs.setContinuousSource(CSAnalytic3d(kCube, [](const Vec3&) { return Metric3d::isotropic(0.25); }));
  const SegmentSource3d seg(Vec3(0.1, 0.1, 0.1), Vec3(0.5, 0.2, 0.3), 0.04);
  const PrismSource3d box = PrismSource3d::box(Vec3(0.6, 0.6, 0.2), Vec3(0.9, 0.8, 0.35));
  const PointSource3d ball(Vec3(0.3, 0.8, 0.7), 0.06);
  const Metric3d flat = Metric3d::fromDirections(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), 0.05, 0.05, 0.01);
  cs.insertExtendedSource(seg, Metric3d::isotropic(0.01));
  cs.insertExtendedSource(box, flat);
  cs.insertExtendedSource(ball, Metric3d::isotropic(0.015));
  cs.validate();
  int inSeg = 0, inBox = 0, inBall = 0;
  cs.forEachControlVertex([&](const Vec3& p, const Metric3d& m) {
    if (seg.contains(p)) {
      ++inSeg;
      EXPECT_TRUE(atMost3d(m, Metric3d::isotropic(0.01))) << p.transpose();
    }
    if (box.contains(p)) {
      ++inBox;
      EXPECT_TRUE(atMost3d(m, flat)) << p.transpose();
    }
    if (ball.contains(p)) {
      ++inBall;
      EXPECT_TRUE(atMost3d(m, Metric3d::isotropic(0.015))) << p.transpose();
    }
  });
  EXPECT_GT(inSeg, 10);
  EXPECT_GT(inBox, 10);
  EXPECT_GT(inBall, 10);
  EXPECT_LE(cs.getMetric(Vec3(0.3, 0.15, 0.2)).lengthAlong(Vec3(1, 1, 1)), 0.01 * (1 + 1e-9));
  EXPECT_LE(cs.getMetric(Vec3(0.75, 0.7, 0.27)).lengthAlong(Vec3(0, 0, 1)), 0.01 * (1 + 1e-9));
  EXPECT_NEAR(cs.getMetric(Vec3(0.95, 0.05, 0.95)).lengthAlong(Vec3(1, 0, 0)), 0.25, 1e-9);
}

TEST(ControlSources, PrismContainmentAndChecks) {
  const PrismSource3d tri({Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0, 1, 1)}, 0.2);
  EXPECT_TRUE(tri.contains(Vec3(0.2, 0.2, 1.09)));
  EXPECT_TRUE(tri.contains(Vec3(0.5, 0.5, 1.0)));  // on the hypotenuse
  EXPECT_FALSE(tri.contains(Vec3(0.6, 0.6, 1.0)));
  EXPECT_FALSE(tri.contains(Vec3(0.2, 0.2, 1.11)));
  EXPECT_THROW(PrismSource3d({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0.5), Vec3(0, 1, 0)}, 0.1), InputError);
  EXPECT_THROW(PrismSource3d({Vec3(0, 0, 0), Vec3(1, 0, 0)}, 0.1), InputError);
  // Samples cover the caps at spacing ≤ the requested lengths.
  const Metric3d m = Metric3d::isotropic(0.1);
  const std::vector<Vec3> pts = tri.samplePoints(m);
  for (const Vec3& p : pts) EXPECT_TRUE(tri.contains(p)) << p.transpose();
  EXPECT_GT(pts.size(), 2u * 50);
}

TEST(ControlSources, SuperpositionOfEqualStructuresIsIntersectionAtControlVertices) {
  const auto fA = [](const Vec2& p) { return Metric2d::fromAngle(0.3 * p.x(), 0.02 + 0.05 * p.y(), 0.08); };
  const auto fB = [](const Vec2& p) { return Metric2d::fromAngle(1.2 - p.y(), 0.03, 0.05 + 0.04 * p.x()); };
  const auto shape = [](const Vec2& p) { return Metric2d::isotropic(0.01 + 0.2 * (p - Vec2(0.4, 0.6)).squaredNorm()); };
  CSQuadtree2d a(kSquare, SizingParameters{}), b(kSquare, SizingParameters{});
  a.setContinuousSource(CSAnalytic2d(kSquare, shape));
  b.setContinuousSource(CSAnalytic2d(kSquare, shape));
  ASSERT_EQ(a.controlVertexCount(), b.controlVertexCount());
  a.modifyControlVertices([&](const Vec2& p, Metric2d& m) { return m = fA(p), true; });
  b.modifyControlVertices([&](const Vec2& p, Metric2d& m) { return m = fB(p), true; });
  a.superpose(b);
  a.validate();
  EXPECT_EQ(a.controlVertexCount(), b.controlVertexCount());
  a.forEachControlVertex([&](const Vec2& p, const Metric2d& m) {
    EXPECT_LT(metricDifference(m, intersect(fA(p), fB(p))), 1e-9) << p.transpose();
  });
}

TEST(ControlSources, SuperpositionRefinesAndIsFinerThanBothSpaces) {
  CSQuadtree2d a = uniformQuadtree(0.1);
  CSQuadtree2d b = uniformQuadtree(0.2);
  b.insertDiscreteSource(Vec2(0.7, 0.3), Metric2d::fromAngle(0.5, 0.002, 0.02));
  const std::size_t leavesBefore = a.leafCount();
  a.superpose(b);
  a.validate();
  EXPECT_GT(a.leafCount(), leavesBefore);
  a.forEachControlVertex([&](const Vec2& p, const Metric2d& m) {
    EXPECT_TRUE(atMost2d(m, b.getMetric(p).sizing)) << p.transpose();
    EXPECT_TRUE(atMost2d(m, Metric2d::isotropic(0.1))) << p.transpose();
  });
  EXPECT_LT(a.getMetric(Vec2(0.7, 0.3)).sizing.lengthAlong(Vec2(std::cos(0.5), std::sin(0.5))), 0.0021);
  // A non-adaptive space is superposed as a continuous source.
  CSQuadtree2d c = uniformQuadtree(0.1);
  const CSAnalytic2d fine(kSquare, [](const Vec2& p) { return Metric2d::isotropic(p.x() < 0.5 ? 0.1 : 0.01); });
  c.superpose(fine);
  c.validate();
  EXPECT_NEAR(c.getMetric(Vec2(0.9, 0.5)).sizing.lengthAlong(Vec2(1, 0)), 0.01, 1e-9);
  // Coarse leaves reaching the jump at x = 0.5 interpolate towards 0.01 (finer, never coarser).
  const double left = c.getMetric(Vec2(0.1, 0.5)).sizing.lengthAlong(Vec2(1, 0));
  EXPECT_LE(left, 0.1 + 1e-9);
  EXPECT_GT(left, 0.05);
}

TEST(ControlSources, SuperpositionIn3d) {
  CSOctree3d a(kCube, SizingParameters{}), b(kCube, SizingParameters{});
  a.setContinuousSource(CSAnalytic3d(kCube, [](const Vec3&) { return Metric3d::isotropic(0.2); }));
  b.setContinuousSource(CSAnalytic3d(kCube, [](const Vec3& p) { return Metric3d::isotropic(0.05 + 0.2 * p.x()); }));
  b.insertDiscreteSource(Vec3(0.2, 0.7, 0.4), Metric3d::isotropic(0.005));
  a.superpose(b);
  a.validate();
  a.forEachControlVertex([&](const Vec3& p, const Metric3d& m) {
    EXPECT_TRUE(atMost3d(m, b.getMetric(p))) << p.transpose();
    EXPECT_TRUE(atMost3d(m, Metric3d::isotropic(0.2))) << p.transpose();
  });
  EXPECT_LT(a.getMetric(Vec3(0.2, 0.7, 0.4)).lengthAlong(Vec3(1, 0, 0)), 0.0051);
}
