// CSQuadtree2d (sec. 3.3): refinement rules, continuous sources, balance, continuity of the
// interpolated field, gradation smoothing, adaptation to parameterization, export.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>
#include <vector>

#include "mesher/control/CSAnalytic2d.h"
#include "mesher/control/CSQuadtree2d.h"
#include "mesher/control/MetricQueryCache.h"
#include "mesher/core/Error.h"
#include "mesher/geometry/SphereSurface.h"
#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricGradation.h"
#include "control_fixtures.h"

using namespace aniso;
using namespace aniso::testing;

namespace {

/// Edge length of the leaf containing uv (largest extent).
double leafSizeAt(const CSQuadtree2d& cs, const Vec2& uv) {
  const auto& tree = cs.structure().tree();
  return tree.nodeSize(tree.locate(uv)).maxCoeff();
}

std::vector<Vec2> directions(int n) {
  std::vector<Vec2> d;
  for (int i = 0; i < n; ++i) d.emplace_back(std::cos(kPi * i / n), std::sin(kPi * i / n));
  return d;
}

/// The bound of MetricGradation.h for every leaf edge (both directions, sampled u).
void expectGradedEdges(const TreeControlSpace<2>& s, double gamma) {
  const auto dirs = directions(24);
  int checked = 0;
  for (const auto& e : s.edges()) {
    Vec2 d = s.tree().point(e.b) - s.tree().point(e.a);
    if (s.hasAux()) d = 0.5 * (s.vertexAux(e.a) + s.vertexAux(e.b)) * d;
    const Metric2d& ma = s.vertexMetric(e.a);
    const Metric2d& mb = s.vertexMetric(e.b);
    const double f = gradationFactor(ma.lengthAlong(d), mb.lengthAlong(d), d.norm(), gamma);
    for (const Vec2& u : dirs) {
      const double ha = ma.lengthAlong(u), hb = mb.lengthAlong(u);
      ASSERT_LE(ha, f * hb * (1 + 1e-6)) << "edge " << e.a << "-" << e.b;
      ASSERT_LE(hb, f * ha * (1 + 1e-6)) << "edge " << e.a << "-" << e.b;
    }
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace

TEST(ControlQuadtree, PointSourceRefinesAroundItWhenInitialized) {
  SizingParameters params;
  CSQuadtree2d cs(box2(0, 0, 1, 1), params);
  cs.setContinuousSource(CSAnalytic2d(box2(0, 0, 1, 1), [](const Vec2&) { return Metric2d::isotropic(0.1); }));
  cs.validate();
  const std::size_t before = cs.leafCount();
  const Vec2 q(0.31, 0.62);
  cs.insertDiscreteSource(q, Metric2d::isotropic(0.002));
  cs.validate();
  EXPECT_GT(cs.leafCount(), before);
  EXPECT_LT(leafSizeAt(cs, q), 0.002 * params.adaptLengthMax * 1.0001);
  EXPECT_GT(leafSizeAt(cs, Vec2(0.95, 0.05)), 10 * leafSizeAt(cs, q));
  // The metric at the source is the source's, far away the default.
  EXPECT_NEAR(cs.getMetric(q).sizing.lengthAlong(Vec2(1, 0)), 0.002, 1e-9);
  EXPECT_NEAR(cs.getMetric(Vec2(0.95, 0.05)).sizing.lengthAlong(Vec2(1, 0)), 0.1, 1e-9);
}

TEST(ControlQuadtree, InitialPointSourcesSplitAndInitialize) {
  SizingParameters params;
  CSQuadtree2d cs(box2(0, 0, 2, 1), params);
  EXPECT_FALSE(cs.initialized());
  EXPECT_THROW(cs.getMetric(Vec2(0.5, 0.5)), MeshingError);
  // Proximity: two sources closer than ε_M are combined (intersection).
  cs.insertDiscreteSource(Vec2(0.5, 0.5), Metric2d::fromAngle(0, 0.01, 0.05));
  cs.insertDiscreteSource(Vec2(0.5, 0.5), Metric2d::fromAngle(kPi / 2, 0.01, 0.05));
  EXPECT_EQ(cs.pendingSourceCount(), 1u);
  cs.validate();
  // Size sensitivity: the leaf of the source is at most l_Mmax long in its metric.
  EXPECT_LE(leafSizeAt(cs, Vec2(0.5, 0.5)), 0.01 * params.adaptLengthMax);
  // Metric difference: two coarse but different sources in one root cell are separated.
  cs.insertDiscreteSource(Vec2(1.2, 0.2), Metric2d::isotropic(0.4));
  cs.insertDiscreteSource(Vec2(1.8, 0.8), Metric2d::isotropic(0.2));
  cs.validate();
  EXPECT_NE(cs.structure().tree().locate(Vec2(1.2, 0.2)), cs.structure().tree().locate(Vec2(1.8, 0.8)));
  cs.initializeControlVertices();
  cs.validate();
  EXPECT_TRUE(cs.initialized());
  EXPECT_EQ(cs.pendingSourceCount(), 0u);
  // The combined source is isotropic 0.01 near (0.5, 0.5); extrapolation reaches everything.
  const Metric2d m = cs.getMetric(Vec2(0.5, 0.5)).sizing;
  EXPECT_NEAR(m.lengthAlong(Vec2(1, 0)), 0.01, 1e-3);
  EXPECT_NEAR(m.lengthAlong(Vec2(0, 1)), 0.01, 1e-3);
  std::size_t visited = 0;
  cs.forEachControlVertex([&](const Vec2&, const Metric2d& mv) {
    ++visited;
    EXPECT_TRUE(mv.matrix().allFinite());
  });
  EXPECT_EQ(visited, cs.controlVertexCount());
}

TEST(ControlQuadtree, MergedPointSourceIsComparedAtTheLeafsNextInsertion) {
  // ε_δ 0.2: isotropic sizes h, h' differ by √2 |h/h' + h'/h - 2|: 0.2 / 0.4 by 0.71,
  // 0.28 by 0.16 from 0.2 and 0.18 from 0.4. The box is short in every size (size rule idle).
  SizingParameters params;
  CSQuadtree2d cs(box2(0, 0, 0.35, 0.35), params);
  const Vec2 a(0.1, 0.1), c(0.3, 0.3);
  cs.insertDiscreteSource(a, Metric2d::isotropic(0.4));
  cs.insertDiscreteSource(c, Metric2d::isotropic(0.4));
  EXPECT_EQ(cs.leafCount(), 1u);
  // merged into a's source (0.2 now), unlike c's: compared when the leaf takes the next one
  cs.insertDiscreteSource(a, Metric2d::isotropic(0.2));
  EXPECT_EQ(cs.pendingSourceCount(), 2u);
  cs.insertDiscreteSource(Vec2(0.3, 0.1), Metric2d::isotropic(0.28));
  cs.validate();
  const auto& tree = cs.structure().tree();
  EXPECT_NE(tree.locate(a), tree.locate(c));
}

TEST(ControlQuadtree, ContinuousSourceFoldsInSourcesCollectedBefore) {
  SizingParameters params;
  CSQuadtree2d cs(box2(0, 0, 1, 1), params);
  cs.insertDiscreteSource(Vec2(0.2, 0.3), Metric2d::isotropic(0.003));
  cs.insertExtendedSource(PointSource2d(Vec2(0.7, 0.7), 0.05), Metric2d::isotropic(0.01));
  EXPECT_GT(cs.pendingSourceCount(), 0u);
  cs.setContinuousSource(CSAnalytic2d(box2(0, 0, 1, 1), [](const Vec2&) { return Metric2d::isotropic(0.1); }));
  cs.validate();
  EXPECT_EQ(cs.pendingSourceCount(), 0u);
  EXPECT_LE(cs.getMetric(Vec2(0.2, 0.3)).sizing.lengthAlong(Vec2(1, 0)), 0.0031);
  EXPECT_LE(cs.getMetric(Vec2(0.7, 0.7)).sizing.lengthAlong(Vec2(1, 0)), 0.01 * (1 + 1e-9));
  EXPECT_NEAR(cs.getMetric(Vec2(0.95, 0.05)).sizing.lengthAlong(Vec2(1, 0)), 0.1, 1e-9);
}

TEST(ControlQuadtree, ConcurrentQueriesMatchSerialOnes) {
  SizingParameters params;
  const SphereSurface sphere(Frame(), 1.0);
  const Box2 patch = box2(0, 0.2, kPi / 2, kPi / 2);
  CSQuadtree2d cs(patch, params);
  cs.setContinuousSource(CSAnalytic2d(patch, swirl));
  cs.adaptToParameterization(sphere, 1e-6);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-0.1, 1.7);
  std::vector<Vec2> pts(20000);
  for (Vec2& p : pts) p = Vec2(u(rng), u(rng));
  std::vector<Mat2> serial(pts.size()), parallel(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) serial[i] = cs.getMetric(pts[i]).transformation();
  auto work = [&](std::size_t first) {
    for (std::size_t i = first; i < pts.size(); i += 2) parallel[i] = cs.getMetric(pts[i]).transformation();
  };
  std::thread a(work, 0), b(work, 1);
  a.join();
  b.join();
  for (std::size_t i = 0; i < pts.size(); ++i) ASSERT_EQ(serial[i], parallel[i]) << i;
}

TEST(ControlQuadtree, ContinuousAN1IsWithinMetricDifferenceAtEveryLeafCentre) {
  SizingParameters params;
  const double k = 1.0;
  const std::string h1 = std::to_string(0.01 * k), h2 = std::to_string(k) + "*(0.0101-0.005*u)";
  const CSAnalytic2d an1(box2(0, 0, 2, 1), "pi/6", h1, h2);
  CSQuadtree2d cs(box2(0, 0, 2, 1), params);
  cs.setContinuousSource(an1);
  cs.validate();
  const auto& tree = cs.structure().tree();
  for (int leaf : tree.leaves()) {
    const Vec2 c = tree.nodeCentre(leaf);
    EXPECT_LE(metricDifference(cs.getMetric(c).sizing, an1.getMetric(c).sizing), params.metricDifferenceEps)
        << "leaf centre " << c.transpose();
  }
  // AN1 is linear in the length tensor along u: eq. 2.18 reproduces it exactly.
  for (const Vec2& p : {Vec2(0.3, 0.1), Vec2(1.7, 0.9), Vec2(1.99, 0.5)})
    EXPECT_LT(metricDifference(cs.getMetric(p).sizing, an1.getMetric(p).sizing), 1e-9);
}

TEST(ControlQuadtree, ContinuousVaryingSourceRefinesUntilLeafCentresMatch) {
  SizingParameters params;
  CSQuadtree2d cs(box2(0, 0, 1, 1), params);
  cs.setContinuousSource(CSAnalytic2d(box2(0, 0, 1, 1), swirl));
  cs.validate();
  EXPECT_GT(cs.leafCount(), 16u);
  RecordProperty("leaves", int(cs.leafCount()));
  const auto& tree = cs.structure().tree();
  for (int leaf : tree.leaves()) {
    const Vec2 c = tree.nodeCentre(leaf);
    EXPECT_LE(metricDifference(cs.getMetric(c).sizing, swirl(c)), params.metricDifferenceEps) << c.transpose();
  }
  // Every control vertex carries the source's metric exactly.
  cs.forEachControlVertex([](const Vec2& p, const Metric2d& m) { EXPECT_LT(metricDifference(m, swirl(p)), 1e-9); });
}

TEST(ControlQuadtree, DiscontinuousSourceStopsAtTheResolutionLimit) {
  SizingParameters params;
  TreeLimits limits;
  CSAnalytic2d jump(box2(0, 0, 1, 1), [](const Vec2&) { return Metric2d::isotropic(0.05); });
  jump.addRegion(box2(1.0 / 3, 0, 1, 1), [](const Vec2&) { return Metric2d::isotropic(0.01); });
  CSQuadtree2d cs(box2(0, 0, 1, 1), params, limits);
  cs.setContinuousSource(jump);
  cs.validate();
  const auto& tree = cs.structure().tree();
  int unresolved = 0;
  for (int leaf : tree.leaves()) {
    const Vec2 c = tree.nodeCentre(leaf);
    if (metricDifference(cs.getMetric(c).sizing, jump.getMetric(c).sizing) <= params.metricDifferenceEps) continue;
    ++unresolved;
    // Only leaves below the resolution limit (in the finer metric h = 0.01 of a corner) stay
    // unresolved.
    EXPECT_LT(tree.nodeSize(leaf).maxCoeff() / 0.01, limits.minLeafMetricLength) << c.transpose();
  }
  EXPECT_GT(unresolved, 0);
  EXPECT_LT(cs.leafCount(), 20000u);
}

TEST(ControlQuadtree, FieldIsContinuousAcrossLevelsAndExactAtVertices) {
  SizingParameters params;
  CSQuadtree2d cs(box2(0, 0, 1, 1), params);
  cs.setContinuousSource(CSAnalytic2d(box2(0, 0, 1, 1), swirl));
  cs.insertDiscreteSource(Vec2(0.8, 0.2), Metric2d::isotropic(0.001));
  cs.validate();
  const auto& s = cs.structure();
  const auto& tree = s.tree();
  int hanging = 0;
  for (int leaf : tree.leaves())
    for (int slot = 0; slot < BalancedTree<2>::kExtraSlots; ++slot) hanging += tree.extra(leaf, slot) >= 0;
  EXPECT_GT(hanging, 0) << "the test needs leaves with hanging vertices";
  for (int v = 0; v < tree.vertexCount(); ++v)
    EXPECT_LT(metricDifference(cs.getMetric(tree.point(v)).sizing, s.vertexMetric(v)), 1e-9);
  // Both sides of every leaf edge, at several points along it.
  const double eps = 1e-9;
  for (int leaf : tree.leaves()) {
    const Vec2 lo = tree.nodeLo(leaf), size = tree.nodeSize(leaf);
    for (double t : {0.1, 0.25, 0.4, 0.5, 0.77}) {
      for (int k = 0; k < 2; ++k) {
        Vec2 p = lo + t * size;
        p(k) = lo(k);
        if (p(k) - eps <= 0) continue;
        Vec2 a = p, b = p;
        a(k) -= eps;
        b(k) += eps;
        ASSERT_LT(metricDifference(cs.getMetric(a).sizing, cs.getMetric(b).sizing), 1e-5) << p.transpose();
      }
    }
  }
}

TEST(ControlQuadtree, BalancedAfterEveryRandomInsertion) {
  SizingParameters params;
  CSQuadtree2d cs(box2(-1, -1, 3, 1), params);
  std::mt19937 rng(7);
  insertRandomSources2d(cs, rng, -1, 3, -1, 1);
  if (::testing::Test::HasFatalFailure()) return;
  cs.smoothGradation(params.gradation);
  cs.validate();
}

TEST(ControlQuadtree, SmoothingSatisfiesTheGradationBoundOnEveryLeafEdge) {
  SizingParameters params;
  CSQuadtree2d cs(box2(0, 0, 1, 1), params);
  cs.setContinuousSource(CSAnalytic2d(box2(0, 0, 1, 1), [](const Vec2&) { return Metric2d::isotropic(0.2); }));
  cs.insertDiscreteSource(Vec2(0.5, 0.5), Metric2d::fromAngle(0.3, 0.001, 0.01));
  cs.insertDiscreteSource(Vec2(0.1, 0.9), Metric2d::isotropic(0.003));
  const double gamma = 2.0;
  const int sweeps = cs.smoothGradation(gamma);
  EXPECT_GE(sweeps, 2);
  cs.validate();
  expectGradedEdges(cs.structure(), gamma);
  // Smoothing only refines: the sources keep (at most) their lengths.
  EXPECT_LE(cs.getMetric(Vec2(0.5, 0.5)).sizing.lengthAlong(Vec2(std::cos(0.3), std::sin(0.3))), 0.001 * (1 + 1e-9));
  // A second call finds nothing to do.
  EXPECT_EQ(cs.smoothGradation(gamma), 1);
}

TEST(ControlQuadtree, ParameterizationAdaptationRefinesNearTheSpherePole) {
  SizingParameters params;
  const SphereSurface sphere(Frame(), 1.0);
  // A patch reaching the pole v = π/2.
  const Box2 patch = box2(0, 0.2, kPi / 2, kPi / 2);
  CSQuadtree2d cs(patch, params);
  cs.setContinuousSource(CSAnalytic2d(patch, [](const Vec2&) { return Metric2d::isotropic(0.002); }));
  const std::size_t before = cs.leafCount();
  cs.adaptToParameterization(sphere, 1e-6);
  cs.validate();
  EXPECT_GT(cs.leafCount(), before);
  const double nearPole = leafSizeAt(cs, Vec2(0.7, kPi / 2 - 1e-3));
  const double nearEquator = leafSizeAt(cs, Vec2(0.7, 0.21));
  EXPECT_LT(nearPole * 8, nearEquator) << nearPole << " vs " << nearEquator;
  // getMetric returns the cached M_p, close to the exact one; smoothing uses it.
  for (const Vec2& p : {Vec2(0.3, 0.5), Vec2(1.2, 1.4), Vec2(0.9, 1.55)}) {
    const Mat2 exact = sphere.parameterizationTensor(p, 1e-6);
    EXPECT_LT((cs.getMetric(p).parameterization - exact).norm(), 0.2 * exact.norm()) << p.transpose();
  }
  cs.smoothGradation(params.gradation);
  cs.validate();
  expectGradedEdges(cs.structure(), params.gradation);
}

TEST(ControlQuadtree, GridExportMatchesTheStructure) {
  SizingParameters params;
  CSQuadtree2d cs(box2(0, 0, 1, 1), params);
  ControlSpaceGrid fresh = cs.grid();
  EXPECT_EQ(fresh.cellCount(), cs.leafCount());
  EXPECT_TRUE(fresh.metric.empty());
  cs.setContinuousSource(CSAnalytic2d(box2(0, 0, 1, 1), swirl));
  const ControlSpaceGrid g = cs.grid();
  EXPECT_EQ(g.dim, 2);
  EXPECT_EQ(g.cellSize, 4);
  EXPECT_EQ(g.points.size(), cs.controlVertexCount());
  EXPECT_EQ(g.cells.size(), 4 * cs.leafCount());
  ASSERT_EQ(g.metric.size(), g.points.size());
  for (std::size_t c = 0; c < g.cellCount(); ++c) {
    // VTK quad order: counter-clockwise.
    const Vec3 a = g.points[g.cells[4 * c]], b = g.points[g.cells[4 * c + 1]], d = g.points[g.cells[4 * c + 3]];
    EXPECT_GT((b - a).cross(d - a).z(), 0);
  }
  for (std::size_t p = 0; p < g.points.size(); ++p) {
    const Metric2d m = swirl(g.points[p].head<2>());
    EXPECT_NEAR(g.lengths[p](0), m.axes().lengths(0), 1e-9);
    EXPECT_NEAR(g.lengths[p](1), m.axes().lengths(1), 1e-9);
  }
}

TEST(ControlQuadtree, QueryCacheReusesNearbyAndDropsStaleMetrics) {
  SizingParameters params;
  CSQuadtree2d cs(box2(0, 0, 1, 1), params);
  cs.setContinuousSource(CSAnalytic2d(box2(0, 0, 1, 1), [](const Vec2&) { return Metric2d::isotropic(0.1); }));
  MetricQueryCache2d cache(0.05);
  cache.get(cs, Vec2(0.5, 0.5));
  cache.get(cs, Vec2(0.502, 0.5));  // 0.02 metric units away
  EXPECT_EQ(cache.hits(), 1u);
  cache.get(cs, Vec2(0.6, 0.5));  // 1 unit away
  EXPECT_EQ(cache.misses(), 2u);
  cs.insertDiscreteSource(Vec2(0.6, 0.5), Metric2d::isotropic(0.001));
  const SurfaceMetricAt m = cache.get(cs, Vec2(0.6, 0.5));  // same point, but the space changed
  EXPECT_EQ(cache.misses(), 3u);
  EXPECT_NEAR(m.sizing.lengthAlong(Vec2(1, 0)), 0.001, 1e-9);
}

TEST(ControlQuadtree, RejectsBadConstruction) {
  SizingParameters params;
  EXPECT_THROW(CSQuadtree2d(Box2(), params), InputError);
  SizingParameters bad = params;
  bad.metricDifferenceEps = -1;
  EXPECT_THROW(CSQuadtree2d(box2(0, 0, 1, 1), bad), InputError);
  TreeLimits limits;
  limits.maxLevel = 40;
  EXPECT_THROW(CSQuadtree2d(box2(0, 0, 1, 1), params, limits), InputError);
  CSQuadtree2d cs(box2(0, 0, 1, 1), params);
  EXPECT_THROW(cs.initializeControlVertices(), MeshingError);
  EXPECT_THROW(cs.smoothGradation(2.0), MeshingError);
}
