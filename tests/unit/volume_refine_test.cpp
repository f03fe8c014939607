// Tests of the volume refinement (thesis sec. 5.5, mesher/volume/VolumeRefinement.h) on a
// cube whose boundary comes from a Delaunay triangulation (no recovery needed).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/core/Error.h"
#include "mesher/volume/TetQuality.h"
#include "mesher/volume/VolumeControlSpace.h"
#include "mesher/volume/VolumeRefinement.h"
#include "volume_refine_fixture.h"

using namespace aniso;
using namespace aniso::testing;

namespace {

CSAnalytic3d uniform(double h) {
  return CSAnalytic3d(unitBox(), [h](const Vec3&) { return Metric3d::isotropic(h); });
}

TEST(VolumeRefine, SphereQualityOfTheIdealTet) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, std::sqrt(3.0) / 2, 0), d(0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3));
  EXPECT_NEAR(refinementQuality(Metric3d::identity(), a, b, c, d), 1.0, 1e-12);
  // twice the size: circumsphere 8 times larger
  EXPECT_NEAR(refinementQuality(Metric3d::identity(), 2 * a, 2 * b, 2 * c, 2 * d), 0.125, 1e-12);
  // the same tet stretched 4 times along x is ideal in the metric with h_x = 4
  const Vec3 s(4, 1, 1);
  const Metric3d m = Metric3d::fromDirections(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), 4, 1, 1);
  EXPECT_NEAR(refinementQuality(m, a.cwiseProduct(s), b.cwiseProduct(s), c.cwiseProduct(s), d.cwiseProduct(s)), 1.0,
              1e-12);
  // flat tet
  EXPECT_EQ(refinementQuality(Metric3d::identity(), a, b, c, Vec3(0.3, 0.3, 0)), 0.0);
}

TEST(VolumeRefine, RunningPrediction) {
  EXPECT_DOUBLE_EQ(predictTetCount(1000, 0.057, 0.57), 10000.0);
  EXPECT_DOUBLE_EQ(predictTetCount(1000, 0.6, 0.57), 1000.0);
}

TEST(VolumeRefine, FixtureIsASolid) {
  std::set<Triple> boundary;
  const SolidTetMesh s = cubeSolid(4, boundary);
  EXPECT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  EXPECT_NEAR(meshVolume(s.mesh), 1.0, 1e-12);
  EXPECT_EQ(boundary.size(), 6u * 4 * 4 * 2);
}

TEST(VolumeRefine, UniformCubeReachesTheSize) {
  std::set<Triple> boundary;
  SolidTetMesh s = cubeSolid(8, boundary);
  const auto fixed = fixedPositions(s);
  const CSAnalytic3d cs = uniform(0.125);
  const double predicted = predictTetCount(s, cs);
  const VolumeRefineStats st = refineVolume(s, cs);
  ASSERT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  EXPECT_NEAR(meshVolume(s.mesh), 1.0, 1e-12);
  EXPECT_EQ(fixedPositions(s), fixed);
  EXPECT_GT(st.inserted, 100u);
  EXPECT_EQ(st.inserted, st.insertedMLE + st.insertedCCS);
  EXPECT_FALSE(st.budgetExhausted);
  EXPECT_NEAR(st.predictedInitial, predicted, 1e-9 * predicted);
  // tets left below q_t are those at the boundary whose circumcentre is outside (a surface
  // triangle too large for q_t): hardly any with fewer than two surface nodes
  std::size_t innerBad = 0;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k) {
    const del3d::TetId t(k);
    if (!s.mesh.isAlive(t)) continue;
    Vec3 p[4];
    int fixedCount = 0;
    for (int i = 0; i < 4; ++i) {
      p[i] = s.mesh.point(s.mesh.vertex(t, i));
      fixedCount += s.isFixed(s.mesh.vertex(t, i));
    }
    if (fixedCount < 2 && refinementQuality(Metric3d::isotropic(0.125), p[0], p[1], p[2], p[3]) < 0.57) ++innerBad;
  }
  EXPECT_LE(innerBad, st.finalTets / 1000 + 1);
  EXPECT_LT(st.abandoned, st.finalTets / 10);
  TetQualitySummary q;
  accumulateTetQuality(s, &cs, q);
  EXPECT_EQ(q.inverted, 0u);
  // a unit mesh: edges about one unit long, the count near the prediction of eq. 6.2
  EXPECT_GT(q.muM.mean(), 0.8);
  EXPECT_LT(q.muM.mean(), 1.2);
  EXPECT_GT(q.meanRatio.mean(), 0.6);
  EXPECT_GT(static_cast<double>(st.finalTets), 0.5 * predicted);
  EXPECT_LT(static_cast<double>(st.finalTets), 3.0 * predicted);
}

TEST(VolumeRefine, GradedSizeFollowsTheField) {
  std::set<Triple> boundary;
  SolidTetMesh s = cubeSolid(6, boundary);
  const CSAnalytic3d cs(unitBox(), [](const Vec3& x) { return Metric3d::isotropic(0.06 + 0.25 * x.x()); });
  refineVolume(s, cs);
  ASSERT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  EXPECT_NEAR(meshVolume(s.mesh), 1.0, 1e-12);
  TetQualitySummary q;
  accumulateTetQuality(s, &cs, q);
  EXPECT_GT(q.muM.mean(), 0.75);
  EXPECT_LT(q.muM.mean(), 1.25);
  // more vertices on the fine side
  std::size_t low = 0, high = 0;
  for (std::uint32_t v = 0; v < s.mesh.numVertices(); ++v) {
    if (!s.mesh.vertexTet(del3d::VertexId(v)).valid() || s.isFixed(del3d::VertexId(v))) continue;
    (s.mesh.point(del3d::VertexId(v)).x() < 0.5 ? low : high) += 1;
  }
  EXPECT_GT(low, 3 * high);
}

TEST(VolumeRefine, AnisotropicMetric) {
  // A parallelepiped, the cube stretched 4 times along (1, 1, 0), meshed for the metric that
  // stretches the same way: its boundary points are then a unit mesh for that metric.
  const Metric3d stretch = Metric3d::fromDirections(Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3::UnitZ(), 4, 1, 1);
  const Mat3 map = stretch.inverseMatrix();
  std::set<Triple> boundary;
  SolidTetMesh s = cubeSolid(6, boundary, 7, map);
  const Metric3d m = Metric3d::fromDirections(Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3::UnitZ(), 4 / 6.0, 1 / 6.0, 1 / 6.0);
  Box3 box;
  for (int c = 0; c < 8; ++c) box.add(map * Vec3(c & 1, (c >> 1) & 1, (c >> 2) & 1));
  const CSAnalytic3d cs(box, [m](const Vec3&) { return m; });
  const VolumeRefineStats st = refineVolume(s, cs);
  ASSERT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  EXPECT_NEAR(meshVolume(s.mesh), map.determinant(), 1e-12);
  EXPECT_GT(st.insertedCCS, 50u);
  TetQualitySummary q;
  accumulateTetQuality(s, &cs, q);
  EXPECT_GT(q.muM.mean(), 0.9);
  EXPECT_LT(q.muM.mean(), 1.1);
  EXPECT_GT(q.etaM.mean(), 0.75);
  // stretched in space: the Euclidean mean ratio is far below the metric one
  EXPECT_LT(q.meanRatio.mean(), q.etaM.mean() - 0.2);
}

TEST(VolumeRefine, Deterministic) {
  std::set<Triple> boundary;
  SolidTetMesh a = cubeSolid(6, boundary), b = cubeSolid(6, boundary);
  const CSAnalytic3d cs(unitBox(), [](const Vec3& x) { return Metric3d::isotropic(0.08 + 0.1 * x.y()); });
  refineVolume(a, cs);
  refineVolume(b, cs);
  EXPECT_TRUE(sameMesh(a, b));
}

TEST(VolumeRefine, VertexBudgetStops) {
  std::set<Triple> boundary;
  SolidTetMesh s = cubeSolid(4, boundary);
  VolumeRefineOptions o;
  o.maxVertices = s.mesh.numVertices() + 50;
  const VolumeRefineStats st = refineVolume(s, uniform(0.05), o);
  EXPECT_TRUE(st.budgetExhausted);
  EXPECT_LE(s.mesh.numVertices(), o.maxVertices);
  EXPECT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  // the guard relative to the prediction of eq. 6.2 (floored at 10^5 tets)
  SolidTetMesh g = cubeSolid(4, boundary);
  const std::size_t start = g.mesh.numVertices();
  VolumeRefineOptions og;
  og.budgetFactor = 0.004;
  const CSAnalytic3d fine = uniform(0.02);
  const double predicted = predictTetCount(g, fine);
  const VolumeRefineStats sg = refineVolume(g, fine, og);
  EXPECT_TRUE(sg.budgetExhausted);
  EXPECT_LE(static_cast<double>(g.mesh.numVertices()), start + 0.004 * std::max(predicted, 1e5) + 1);
  EXPECT_TRUE(checkSolid(g, boundary).empty()) << joined(checkSolid(g, boundary));
}

TEST(VolumeRefine, ProgressReportsPredictions) {
  std::set<Triple> boundary;
  SolidTetMesh s = cubeSolid(4, boundary);
  VolumeRefineOptions o;
  o.progressInterval = 100;
  std::vector<VolumeRefineProgress> seen;
  o.progress = [&](const VolumeRefineProgress& p) { seen.push_back(p); };
  const VolumeRefineStats st = refineVolume(s, uniform(0.1), o);
  ASSERT_GE(seen.size(), 2u);
  for (const VolumeRefineProgress& p : seen) {
    EXPECT_GE(p.predictedTets, static_cast<double>(p.tets));
    EXPECT_LE(p.tets, st.finalTets + 100);
  }
  // the last prediction is within a factor 2 of the final count (table 6.1)
  EXPECT_GT(seen.back().predictedTets, 0.5 * static_cast<double>(st.finalTets));
  EXPECT_LT(seen.back().predictedTets, 2.0 * static_cast<double>(st.finalTets));
}

}  // namespace

// The sizing convention of VolumeControlSpace.h: the tets are made in M_v = M / f, so their
// interior edges are about f times the size the boundary was made for.
double meanInteriorEdge(const SolidTetMesh& s) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k) {
    const del3d::TetId t(k);
    if (!s.mesh.isAlive(t)) continue;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const del3d::VertexId a = s.mesh.vertex(t, i), b = s.mesh.vertex(t, j);
        if (!s.isFixed(a) && !s.isFixed(b)) edges.insert(std::minmax(a.index, b.index));
      }
  }
  double sum = 0;
  for (const auto& [a, b] : edges)
    sum += (s.mesh.point(del3d::VertexId(a)) - s.mesh.point(del3d::VertexId(b))).norm();
  return edges.empty() ? 0 : sum / static_cast<double>(edges.size());
}

TEST(VolumeRefine, VolumeMetricSpaceScalesEveryLengthButAtTheBoundary) {
  const auto user = std::make_shared<CSAnalytic3d>(unitBox(), [](const Vec3& x) {
    return Metric3d::fromDirections(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), 0.1, 0.2 + x.y(), 0.3);
  });
  const Vec3 x(0.3, 0.6, 0.2), d(1, -2, 0.5), node(0.5, 0.25, 0.0);
  const std::vector<Vec3> boundary{node, Vec3(0, 0, -0.0)};
  const VolumeMetricSpace mv(user, boundary);
  EXPECT_EQ(mv.factor(), kVolumeLengthFactor);
  EXPECT_NEAR(mv.getMetric(x).length(d) * kVolumeLengthFactor, user->getMetric(x).length(d), 1e-12);
  EXPECT_EQ(mv.lengthFactorAt(x), kVolumeLengthFactor);
  // M itself at a surface node (exact coordinates; -0 is 0), M / f a hair away
  EXPECT_EQ(mv.getMetric(node).matrix(), user->getMetric(node).matrix());
  EXPECT_TRUE(mv.onBoundary(Vec3(0, -0.0, 0)));
  EXPECT_EQ(mv.lengthFactorAt(node), 1.0);
  EXPECT_FALSE(mv.onBoundary(Vec3(0.5, std::nextafter(0.25, 1.0), 0.0)));
  EXPECT_EQ(mv.bounds().lo, user->bounds().lo);
  EXPECT_THROW(VolumeMetricSpace(user, {}, 0.0), MeshingError);
  EXPECT_THROW(VolumeMetricSpace(nullptr), MeshingError);
}

std::vector<Vec3> fixedPoints(const SolidTetMesh& s) {
  std::vector<Vec3> out;
  for (std::uint32_t v = 0; v < s.mesh.numVertices(); ++v)
    if (s.isFixed(del3d::VertexId(v))) out.push_back(s.mesh.point(del3d::VertexId(v)));
  return out;
}

TEST(VolumeRefine, RefinementHonoursTheVolumeLengthFactor) {
  const double h = 0.1;
  std::set<Triple> boundary;
  SolidTetMesh plain = cubeSolid(10, boundary), uniformF = cubeSolid(10, boundary), graded = cubeSolid(10, boundary);
  const auto user = std::make_shared<CSAnalytic3d>(uniform(h));
  const VolumeMetricSpace scaled(user), mv(user, fixedPoints(graded));
  refineVolume(plain, *user);
  refineVolume(uniformF, scaled);
  refineVolume(graded, mv);
  ASSERT_TRUE(checkSolid(graded, boundary).empty()) << joined(checkSolid(graded, boundary));
  EXPECT_NEAR(meshVolume(graded.mesh), 1.0, 1e-12);
  // Edges between inner vertices: about unit long in M_v (f h), unit long in M without f.
  const double inner = meanInteriorEdge(uniformF) / (kVolumeLengthFactor * h);
  EXPECT_GT(inner, 0.9);
  EXPECT_LT(inner, 1.1);
  EXPECT_GT(meanInteriorEdge(plain) / h, 0.9);
  EXPECT_LT(meanInteriorEdge(plain) / h, 1.1);
  // With M at the boundary nodes the first layer grades from h: shorter on average, but
  // well above h.
  const double gradedInner = meanInteriorEdge(graded) / h;
  EXPECT_GT(gradedInner, 0.5 * (1 + kVolumeLengthFactor));
  EXPECT_LT(gradedInner, 1.1 * kVolumeLengthFactor);
  // Fewer tets, by less than f³ (the boundary layer keeps some more).
  const double ratio = static_cast<double>(plain.mesh.numTets()) / static_cast<double>(graded.mesh.numTets());
  EXPECT_GT(ratio, 0.4 * std::pow(kVolumeLengthFactor, 3));
  EXPECT_LT(ratio, 1.1 * std::pow(kVolumeLengthFactor, 3));
  // The report's μ_M in the user's metric: f times that in M_v for M / f everywhere; with the
  // boundary at M, between the two.
  TetQualitySummary q, g;
  accumulateTetQuality(uniformF, &scaled, q, &scaled);
  EXPECT_NEAR(q.muMUser.mean(), kVolumeLengthFactor * q.muM.mean(), 1e-12);
  EXPECT_NEAR(q.muMUser.max(), kVolumeLengthFactor * q.muM.max(), 1e-12);
  accumulateTetQuality(graded, &mv, g, &mv);
  EXPECT_GT(g.muMUser.mean(), g.muM.mean());
  EXPECT_LT(g.muMUser.mean(), kVolumeLengthFactor * g.muM.mean());
  EXPECT_GT(g.etaM.mean(), 0.75);
}

TEST(VolumeRefine, VolumeGradationHoldsInTheVolumeMetric) {
  // eq. 2.27's slope a = 2 (γ − 1) / (γ + 1): γ 4 gives 1.2, over f 1.4 0.857..., γ 2.5
  EXPECT_NEAR(volumeGradation(4.0, 1.4), 2.5, 1e-12);
  EXPECT_NEAR(volumeGradation(4.0, 1.0), 4.0, 1e-12);
  EXPECT_EQ(volumeGradation(1.0, 1.4), 1.0);
  EXPECT_LT(volumeGradation(4.0, 2.0), volumeGradation(4.0, 1.5));
}
