// CSOctree3d (sec. 3.3): refinement, continuous sources, balance, continuity across
// hanging vertices (edge midpoints and face centres), gradation, export, thread safety.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <thread>
#include <vector>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/control/CSOctree3d.h"
#include "mesher/control/MetricQueryCache.h"
#include "mesher/core/Error.h"
#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricGradation.h"
#include "control_fixtures.h"

using namespace aniso;
using namespace aniso::testing;

namespace {


double leafSizeAt(const CSOctree3d& cs, const Vec3& x) {
  const auto& tree = cs.structure().tree();
  return tree.nodeSize(tree.locate(x)).maxCoeff();
}

CSAnalytic3d constant(double h) {
  return CSAnalytic3d(kCube, [h](const Vec3&) { return Metric3d::isotropic(h); });
}

std::vector<Vec3> sphereDirections(int n) {
  std::vector<Vec3> d;
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z);
    d.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return d;
}

}  // namespace

TEST(ControlOctree, PointSourceRefinesAroundIt) {
  SizingParameters params;
  CSOctree3d cs(kCube, params);
  cs.setContinuousSource(constant(0.2));
  const std::size_t before = cs.leafCount();
  const Vec3 q(0.3, 0.6, 0.45);
  cs.insertDiscreteSource(q, Metric3d::isotropic(0.004));
  cs.validate();
  EXPECT_GT(cs.leafCount(), before);
  EXPECT_LE(leafSizeAt(cs, q), 0.004 * params.adaptLengthMax);
  EXPECT_GT(leafSizeAt(cs, Vec3(0.95, 0.05, 0.9)), 10 * leafSizeAt(cs, q));
  EXPECT_NEAR(cs.getMetric(q).lengthAlong(Vec3(1, 0, 0)), 0.004, 1e-9);
  EXPECT_NEAR(cs.getMetric(Vec3(0.95, 0.05, 0.9)).lengthAlong(Vec3(0, 0, 1)), 0.2, 1e-9);
}

TEST(ControlOctree, InitialSourcesThenExtrapolation) {
  SizingParameters params;
  CSOctree3d cs(box3(Vec3(0, 0, 0), Vec3(2, 1, 1)), params);
  cs.insertDiscreteSource(Vec3(0.2, 0.2, 0.2), Metric3d::isotropic(0.05));
  cs.insertDiscreteSource(Vec3(1.8, 0.8, 0.8), Metric3d::isotropic(0.2));
  cs.validate();
  EXPECT_EQ(cs.pendingSourceCount(), 2u);
  cs.initializeControlVertices();
  cs.validate();
  EXPECT_LT(cs.getMetric(Vec3(0.2, 0.2, 0.2)).lengthAlong(Vec3(1, 0, 0)), 0.06);
  EXPECT_GT(cs.getMetric(Vec3(1.8, 0.8, 0.8)).lengthAlong(Vec3(1, 0, 0)), 0.15);
}

TEST(ControlOctree, ContinuousSourceIsWithinMetricDifferenceAtEveryLeafCentre) {
  SizingParameters params;
  const CSAnalytic3d source(kCube, twist);
  CSOctree3d cs(kCube, params);
  cs.setContinuousSource(source);
  cs.validate();
  EXPECT_GT(cs.leafCount(), 64u);
  const auto& tree = cs.structure().tree();
  for (int leaf : tree.leaves()) {
    const Vec3 c = tree.nodeCentre(leaf);
    ASSERT_LE(metricDifference(cs.getMetric(c), twist(c)), params.metricDifferenceEps) << c.transpose();
  }
}

TEST(ControlOctree, FieldIsContinuousAcrossHangingEdgeAndFaceVertices) {
  SizingParameters params;
  CSOctree3d cs(kCube, params);
  cs.setContinuousSource(CSAnalytic3d(kCube, twist));
  cs.insertDiscreteSource(Vec3(0.8, 0.2, 0.3), Metric3d::isotropic(0.002));
  cs.validate();
  const auto& s = cs.structure();
  const auto& tree = s.tree();
  int edgeExtras = 0, faceExtras = 0;
  for (int leaf : tree.leaves())
    for (int slot = 0; slot < BalancedTree<3>::kExtraSlots; ++slot) {
      if (tree.extra(leaf, slot) < 0) continue;
      std::array<int, 4> c;
      (BalancedTree<3>::slotCorners(slot, c) == 2 ? edgeExtras : faceExtras)++;
    }
  EXPECT_GT(edgeExtras, 0);
  EXPECT_GT(faceExtras, 0);
  for (int v = 0; v < tree.vertexCount(); ++v)
    ASSERT_LT(metricDifference(cs.getMetric(tree.point(v)), s.vertexMetric(v)), 1e-9);
  const double eps = 1e-9;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> t(0, 1);
  for (int leaf : tree.leaves()) {
    const Vec3 lo = tree.nodeLo(leaf), size = tree.nodeSize(leaf);
    for (int k = 0; k < 3; ++k) {
      if (lo(k) <= 0) continue;
      for (int i = 0; i < 3; ++i) {
        Vec3 p = lo + Vec3(t(rng), t(rng), t(rng)).cwiseProduct(size);
        p(k) = lo(k);
        Vec3 a = p, b = p;
        a(k) -= eps;
        b(k) += eps;
        ASSERT_LT(metricDifference(cs.getMetric(a), cs.getMetric(b)), 1e-5) << p.transpose();
      }
    }
  }
}

TEST(ControlOctree, BalancedAfterEveryOperation) {
  SizingParameters params;
  CSOctree3d cs(box3(Vec3(-1, 0, 0), Vec3(1, 1, 0.5)), params);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> x(-1, 1), y(0, 1), z(0, 0.5), lh(-3, -1);
  for (int i = 0; i < 25; ++i) {
    cs.insertDiscreteSource(Vec3(x(rng), y(rng), z(rng)), Metric3d::isotropic(std::pow(10, lh(rng))));
    ASSERT_NO_THROW(cs.validate()) << "fresh insertion " << i;
  }
  cs.initializeControlVertices();
  cs.validate();
  for (int i = 0; i < 25; ++i) {
    cs.insertDiscreteSource(Vec3(x(rng), y(rng), z(rng)), Metric3d::isotropic(std::pow(10, lh(rng))));
    ASSERT_NO_THROW(cs.validate()) << "update insertion " << i;
  }
  cs.setContinuousSource(CSAnalytic3d(cs.bounds(), twist));
  cs.validate();
  cs.smoothGradation(params.gradation);
  cs.validate();
}

TEST(ControlOctree, SmoothingSatisfiesTheGradationBoundOnEveryLeafEdge) {
  SizingParameters params;
  CSOctree3d cs(kCube, params);
  cs.setContinuousSource(constant(0.25));
  cs.insertDiscreteSource(Vec3(0.5, 0.5, 0.5), Metric3d::fromDirections(Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(0, 0, 1),
                                                                         0.002, 0.01, 0.02));
  const double gamma = 2.0;
  EXPECT_GE(cs.smoothGradation(gamma), 2);
  cs.validate();
  const auto& s = cs.structure();
  const auto dirs = sphereDirections(40);
  for (const auto& e : s.edges()) {
    const Vec3 d = s.tree().point(e.b) - s.tree().point(e.a);
    const Metric3d& ma = s.vertexMetric(e.a);
    const Metric3d& mb = s.vertexMetric(e.b);
    const double f = gradationFactor(ma.lengthAlong(d), mb.lengthAlong(d), d.norm(), gamma);
    for (const Vec3& u : dirs) {
      ASSERT_LE(ma.lengthAlong(u), f * mb.lengthAlong(u) * (1 + 1e-6));
      ASSERT_LE(mb.lengthAlong(u), f * ma.lengthAlong(u) * (1 + 1e-6));
    }
  }
  // Along the edges towards the source the length grows at most linearly with slope
  // a_max = 2(γ−1)/(γ+1) (eq. 2.27) from the source's length along x (about 0.0028).
  const double aMax = gradationSlopeLimit(gamma);
  const double hx = cs.getMetric(Vec3(0.6, 0.5, 0.5)).lengthAlong(Vec3(1, 0, 0));
  EXPECT_LT(hx, 0.0029 + aMax * 0.1 * 1.05);
  EXPECT_LT(hx, 0.25);
}

TEST(ControlOctree, ConcurrentQueriesMatchSerialOnes) {
  SizingParameters params;
  CSOctree3d cs(kCube, params);
  cs.setContinuousSource(CSAnalytic3d(kCube, twist));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  std::vector<Vec3> pts(20000);
  for (Vec3& p : pts) p = Vec3(u(rng), u(rng), u(rng));
  std::vector<Mat3> serial(pts.size()), parallel(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) serial[i] = cs.getMetric(pts[i]).matrix();
  auto work = [&](std::size_t begin) {
    for (std::size_t i = begin; i < pts.size(); i += 2) parallel[i] = cs.getMetric(pts[i]).matrix();
  };
  std::thread a(work, 0), b(work, 1);
  a.join();
  b.join();
  for (std::size_t i = 0; i < pts.size(); ++i) ASSERT_EQ(serial[i], parallel[i]) << i;
}

TEST(ControlOctree, GridExportAndQueryCache) {
  SizingParameters params;
  CSOctree3d cs(kCube, params);
  cs.setContinuousSource(CSAnalytic3d(kCube, twist));
  const ControlSpaceGrid g = cs.grid();
  EXPECT_EQ(g.dim, 3);
  EXPECT_EQ(g.cellSize, 8);
  EXPECT_EQ(g.cells.size(), 8 * cs.leafCount());
  EXPECT_EQ(g.metric.size(), cs.controlVertexCount());
  for (std::size_t c = 0; c < g.cellCount(); ++c) {
    // VTK hexahedron: bottom face counter-clockwise seen from +z, top above it.
    const Vec3 p0 = g.points[g.cells[8 * c]], p1 = g.points[g.cells[8 * c + 1]], p3 = g.points[g.cells[8 * c + 3]],
               p4 = g.points[g.cells[8 * c + 4]];
    ASSERT_GT((p1 - p0).cross(p3 - p0).dot(p4 - p0), 0);
  }
  expectQueryCache3d(cs);
}
