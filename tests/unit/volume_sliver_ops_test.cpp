// Tests of the sliver operators on hand-made configurations: edge removal by quality
// (improve/QualityEdgeRemoval.h) and the Steiner point at a sliver
// (improve/SliverSteinerPoint.h); validateSolidTetMesh (through checkSolid) after each.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/delaunay3d/LocalRetriangulation.h"
#include "mesher/volume/improve/QualityEdgeRemoval.h"
#include "mesher/volume/improve/SliverSteinerPoint.h"
#include "mesher/volume/improve/VertexMetrics.h"
#include "volume_refine_fixture.h"

using namespace aniso;
using namespace aniso::testing;
using del3d::TetId;
using del3d::VertexId;

namespace {

double worstEta(const SolidTetMesh& s, const improve3d::VertexMetrics& vm) {
  double w = 1e300;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k)
    if (s.mesh.isAlive(TetId(k))) w = std::min(w, vm.eta(s.mesh.tetVertices(TetId(k))));
  return w;
}

const CSAnalytic3d& unitSpace() {
  static const CSAnalytic3d cs(Box3(Vec3(-3, -3, -3), Vec3(3, 3, 3)), [](const Vec3&) { return Metric3d::isotropic(1); });
  return cs;
}

/// The bipyramid: edge (0, 1) from (0, 0, -h) to (0, 0, h), ring of 5 tets around it
/// through the regular pentagon 2..6 of radius 1.
SolidTetMesh bipyramid(double h, std::set<Triple>& boundary) {
  std::vector<Vec3> pts = {Vec3(0, 0, -h), Vec3(0, 0, h)};
  std::vector<std::array<int, 4>> tets;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * std::numbers::pi * i / 5;
    pts.emplace_back(std::cos(a), std::sin(a), 0);
    tets.push_back({0, 1, 2 + i, 2 + (i + 1) % 5});
  }
  return solidFrom(pts, tets, boundary);
}

TEST(QualityEdgeRemoval, RemovesTheEdgeOfALongBipyramid) {
  // h = 2: the five needles around the long edge (worst η 0.49) become six tets on the
  // pentagon's fan (worst η 0.67)
  std::set<Triple> boundary;
  SolidTetMesh s = bipyramid(2.0, boundary);
  improve3d::VertexMetrics vm(s.mesh, unitSpace());
  const double before = worstEta(s, vm);
  const TetId t = s.mesh.vertexTet(pv(0));
  std::vector<TetId> created;
  ASSERT_TRUE(improve3d::removeEdgeByQuality(s, vm, t, s.mesh.localIndex(t, pv(0)),
                                             s.mesh.localIndex(t, pv(1)), created));
  EXPECT_EQ(created.size(), 6u);
  EXPECT_EQ(s.mesh.numTets(), 6u);
  ASSERT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  EXPECT_GT(worstEta(s, vm), before + 0.1);
  EXPECT_NEAR(meshVolume(s.mesh), 5 * std::sin(2 * std::numbers::pi / 5) / 2 * 4.0 / 3.0, 1e-12);
}

TEST(QualityEdgeRemoval, KeepsTheEdgeWhenTheRingIsBetter) {
  // h = 0.5: the ring (worst η 0.99) beats every fan (0.56): nothing changes
  std::set<Triple> boundary;
  SolidTetMesh s = bipyramid(0.5, boundary);
  improve3d::VertexMetrics vm(s.mesh, unitSpace());
  const TetId t = s.mesh.vertexTet(pv(0));
  std::vector<TetId> created;
  EXPECT_FALSE(improve3d::removeEdgeByQuality(s, vm, t, s.mesh.localIndex(t, pv(0)),
                                              s.mesh.localIndex(t, pv(1)), created));
  EXPECT_TRUE(created.empty());
  EXPECT_EQ(s.mesh.numTets(), 5u);
  EXPECT_TRUE(checkSolid(s, boundary).empty());
}

/// A pyramid over the square a b c d whose base folds by `lift` along the diagonal ac
/// (b and d lifted): the flat tet abcd carries the two base triangles abc and acd (the
/// boundary sliver of a nearly flat fold), the tets abde and cbde fill the rest.
SolidTetMesh flatCap(double lift, std::set<Triple>& boundary) {
  const std::vector<Vec3> pts = {Vec3(0, 0, 0), Vec3(1, 0, lift), Vec3(1, 1, 0), Vec3(0, 1, lift), Vec3(0.5, 0.5, 0.8)};
  return solidFrom(pts, {{0, 1, 2, 3}, {0, 1, 3, 4}, {2, 1, 3, 4}}, boundary);
}

TEST(SliverSteinerPoint, SplitsAFlatCapOnTwoBoundaryFaces) {
  std::set<Triple> boundary;
  SolidTetMesh s = flatCap(0.01, boundary);
  ASSERT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  improve3d::VertexMetrics vm(s.mesh, unitSpace());
  const double before = worstEta(s, vm), volume = meshVolume(s.mesh);
  ASSERT_LT(before, 0.1);
  TetId cap;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k)
    if (s.mesh.isAlive(TetId(k)) && s.mesh.localIndex(TetId(k), pv(4)) < 0) cap = TetId(k);
  ASSERT_TRUE(cap.valid());
  std::vector<TetId> created;
  const VertexId v = improve3d::insertSteinerPointAtSliver(s, vm, cap, created);
  ASSERT_TRUE(v.valid());
  EXPECT_FALSE(s.isFixed(v));
  EXPECT_FALSE(s.mesh.isAlive(cap) && s.mesh.localIndex(cap, pv(4)) < 0);
  ASSERT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  EXPECT_NEAR(meshVolume(s.mesh), volume, 1e-12);
  EXPECT_GT(worstEta(s, vm), before + 0.2);
  for (const TetId u : created) EXPECT_GE(s.mesh.localIndex(u, v), 0);
}

TEST(SliverSteinerPoint, LeavesAGoodTetAlone) {
  // the regular-ish pyramid halves: no region around a good tet gets better
  std::set<Triple> boundary;
  SolidTetMesh s = flatCap(-0.5, boundary);  // b, d lowered: abcd is a proper tet
  improve3d::VertexMetrics vm(s.mesh, unitSpace());
  const double before = worstEta(s, vm);
  ASSERT_GT(before, 0.3);
  const std::size_t vertices = s.mesh.numVertices();
  TetId best;
  double bestEta = -1;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k)
    if (s.mesh.isAlive(TetId(k)) && vm.eta(s.mesh.tetVertices(TetId(k))) > bestEta)
      best = TetId(k), bestEta = vm.eta(s.mesh.tetVertices(TetId(k)));
  std::vector<TetId> created;
  const VertexId v = improve3d::insertSteinerPointAtSliver(s, vm, best, created);
  if (v.valid()) EXPECT_GT(worstEta(s, vm), before);  // only ever an improvement
  else EXPECT_EQ(s.mesh.numVertices(), vertices);
  EXPECT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
}

}  // namespace

// The sliver phase's score (VertexMetrics with the Euclidean guard) ranks a flat sliver
// (dihedral 1.6 deg, mean ratio 0.088) below a spire (three close vertices, every dihedral
// angle >= 60 deg, mean ratio 0.042), though the mean ratio alone ranks them the other way
// round: operators maximising the worst score then stop trading spires for slivers.
TEST(VertexMetrics, GuardRanksASliverBelowASpire) {
  const del3d::TetMesh empty;
  improve3d::VertexMetrics vm(empty, unitSpace());
  const double s = 0.05, h = 0.02;
  const Vec3 spire[4] = {Vec3(0, 0, 0), Vec3(s, 0, 0), Vec3(s / 2, s * std::sqrt(3.0) / 2, 0),
                         Vec3(s / 2, s * std::sqrt(3.0) / 6, 1)};
  const Vec3 sliver[4] = {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, h), Vec3(0, -1, h)};
  const Mat3 id = Mat3::Identity();
  const auto positive = [&](const Vec3* p) { return (p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])) > 0; };
  ASSERT_TRUE(positive(spire));
  ASSERT_TRUE(positive(sliver));
  EXPECT_LT(vm.scorePoints(spire, id, true), vm.scorePoints(sliver, id, true));
  vm.setGuardEuclidean(true);
  EXPECT_GT(vm.scorePoints(spire, id, true), vm.scorePoints(sliver, id, true));
  // the guard never raises a score, and a regular tet keeps its score of 1
  const Vec3 regular[4] = {Vec3(1, 1, 1), Vec3(1, -1, -1), Vec3(-1, 1, -1), Vec3(-1, -1, 1)};
  const Vec3* reg = positive(regular) ? regular : nullptr;
  const Vec3 flipped[4] = {regular[1], regular[0], regular[2], regular[3]};
  EXPECT_NEAR(vm.scorePoints(reg ? reg : flipped, id, true), 1.0, 1e-9);
  vm.setGuardEuclidean(false);
  EXPECT_NEAR(vm.scorePoints(reg ? reg : flipped, id, true), 1.0, 1e-9);
}
