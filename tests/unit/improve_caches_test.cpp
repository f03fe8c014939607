// Tests of the caches of the volume improvement (mesher/volume/improve/TetScores.h,
// VertexTets.h) and of the acos-free dihedral test (TetQuality.h dihedralCosineOutside).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/volume/TetQuality.h"
#include "mesher/volume/VolumeImprovement.h"
#include "mesher/volume/VolumeRefinement.h"
#include "mesher/volume/improve/QualityFlips.h"
#include "mesher/volume/improve/SliverRemoval.h"
#include "mesher/volume/improve/TetScores.h"
#include "mesher/volume/improve/TetStar.h"
#include "mesher/volume/improve/VertexMover.h"
#include "mesher/volume/improve/VertexTets.h"
#include "volume_refine_fixture.h"

using namespace aniso;
using namespace aniso::testing;

namespace {

constexpr double kDegToRad = 0.017453292519943295;

/// Graded fields in which a moved vertex's tensor changes.
CSAnalytic3d gradedAnisotropic() {
  return CSAnalytic3d(unitBox(), [](const Vec3& x) {
    return Metric3d::fromDirections(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), 0.08 + 0.1 * x.x(), 0.15,
                                    0.1 + 0.05 * x.z());
  });
}
CSAnalytic3d gradedIsotropic() {
  return CSAnalytic3d(unitBox(), [](const Vec3& x) { return Metric3d::isotropic(0.06 + 0.12 * x.z()); });
}

TEST(DihedralCosineOutside, AgreesWithTheAngles) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int outside = 0, inside = 0;
  for (int k = 0; k < 4000; ++k) {
    Vec3 p[4];
    for (auto& q : p) q = Vec3(u(rng), u(rng), u(rng));
    if (k % 3 == 0) p[3] = 0.5 * (p[0] + p[1]) + 0.02 * (p[3] - p[2]);  // flat ones too
    const DihedralRange r = tetDihedralRange(p[0], p[1], p[2], p[3]);
    for (const double lo : {5.0, 15.0, 30.0})
      for (const double hi : {175.0, 165.0}) {
        const bool expected = r.minDeg < lo || r.maxDeg > hi;
        // angles within 1e-9° of a threshold may fall either way
        if (std::abs(r.minDeg - lo) < 1e-9 || std::abs(r.maxDeg - hi) < 1e-9) continue;
        EXPECT_EQ(dihedralCosineOutside(p[0], p[1], p[2], p[3], std::cos(lo * kDegToRad), std::cos(hi * kDegToRad)),
                  expected)
            << k << " " << r.minDeg << " " << r.maxDeg;
        ++(expected ? outside : inside);
      }
    // either orientation
    EXPECT_EQ(dihedralCosineOutside(p[0], p[2], p[1], p[3], std::cos(15 * kDegToRad), std::cos(165 * kDegToRad)),
              dihedralCosineOutside(p[0], p[1], p[2], p[3], std::cos(15 * kDegToRad), std::cos(165 * kDegToRad)));
  }
  EXPECT_GT(outside, 1000);  // both answers are exercised
  EXPECT_GT(inside, 1000);
}

// A certified score has the sign of orient3d (the convention legal() relies on), and the
// certificate holds for flat tets down to the threshold.
TEST(VertexMetrics, OrientationCertificateAgreesWithOrient3d) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  del3d::TetMesh mesh;
  const CSAnalytic3d cs(unitBox(), [](const Vec3&) { return Metric3d::isotropic(0.1); });
  improve3d::VertexMetrics vm(mesh, cs);
  int certified = 0;
  for (int k = 0; k < 20000; ++k) {
    Vec3 p[4];
    for (auto& q : p) q = Vec3(u(rng), u(rng), u(rng)) * std::pow(10.0, (k % 7) - 3);
    if (k % 2) p[3] = p[0] + 0.3 * (p[1] - p[0]) + 0.6 * (p[2] - p[0]) + std::pow(10.0, -(k % 9)) * (p[3] - p[0]);
    const double s = vm.scorePoints(p, Mat3::Identity(), true);
    if (s <= improve3d::kOrientationCertificate) continue;
    ++certified;
    EXPECT_GT(predicates::orient3d(p[0].data(), p[1].data(), p[2].data(), p[3].data()), 0) << k;
  }
  EXPECT_GT(certified, 5000);
}

TEST(VertexTets, RowsAreTheStars) {
  std::set<Triple> boundary;
  SolidTetMesh s = cubeSolid(5, boundary);
  const CSAnalytic3d cs(unitBox(), [](const Vec3&) { return Metric3d::isotropic(0.2); });
  refineVolume(s, cs);
  const improve3d::VertexTets inc(s.mesh);
  ASSERT_EQ(inc.numVertices(), s.mesh.numVertices());
  std::vector<del3d::TetId> star;
  for (std::uint32_t v = 0; v < s.mesh.numVertices(); ++v) {
    improve3d::vertexStar(s.mesh, del3d::VertexId(v), star);
    std::vector<std::uint32_t> walked;
    for (const del3d::TetId t : star) walked.push_back(t.index);
    std::sort(walked.begin(), walked.end());
    const auto row = inc.of(del3d::VertexId(v));
    EXPECT_EQ(std::vector<std::uint32_t>(row.begin(), row.end()), walked) << v;
  }
}

// Smoothing and flips keep the score cache exact (TetScores' contract) where a moved
// vertex's tensor changes: a graded anisotropic field and a graded isotropic one.
void checkCacheStaysExact(const ControlSpace3d& cs) {
  std::set<Triple> boundary;
  SolidTetMesh s = cubeSolid(6, boundary);
  refineVolume(s, cs);
  s.node.resize(s.mesh.numVertices(), -1);
  improve3d::VertexMetrics vm(s.mesh, cs);
  improve3d::TetScores scores(s.mesh, vm);
  ASSERT_TRUE(scores.valid());
  improve3d::VertexMover mover(s, vm);
  mover.setScores(&scores);
  {
    const improve3d::VertexTets inc(s.mesh);
    mover.setIncidence(&inc);
    std::size_t moved = 0;
    for (std::uint32_t v = 0; v < s.mesh.numVertices(); ++v) moved += mover.smooth(del3d::VertexId(v), 0.05, 0.3);
    for (std::uint32_t v = 0; v < s.mesh.numVertices(); ++v) moved += mover.smooth(del3d::VertexId(v), 0.05, 0.3, true);
    EXPECT_GT(moved, 0u);
    mover.setIncidence(nullptr);
  }
  EXPECT_TRUE(scores.valid());
  improve3d::QualityFlips flips(s, vm, 1e-3, &scores);
  flips.run(2.0);
  EXPECT_GT(flips.counts().total(), 0u);
  EXPECT_TRUE(scores.valid());
  // the sliver scan reading the cache finds the same slivers
  for (const double angle : {15.0, 30.0, 60.0}) {
    const auto slivers = improve3d::liveSlivers(s, vm, angle, 5.0);
    EXPECT_EQ(improve3d::liveSlivers(s, vm, angle, 5.0, &scores), slivers);
    if (angle == 60.0) EXPECT_FALSE(slivers.empty());
  }
  EXPECT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
}

TEST(TetScores, StaysExactThroughSmoothingAndFlips) {
  checkCacheStaysExact(gradedAnisotropic());
  checkCacheStaysExact(gradedIsotropic());
}

}  // namespace

namespace {

// The report reads the improvement's tensors (accumulateTetQuality with metrics) and gets
// exactly what it gets by querying the control space again.
void checkReportFromImprovementTensors(const ControlSpace3d& cs) {
  std::set<Triple> boundary;
  SolidTetMesh s = cubeSolid(6, boundary);
  refineVolume(s, cs);
  improve3d::VertexMetrics vm(s.mesh, cs);
  improveVolume(s, cs, {}, &vm);
  TetQualitySummary queried, read;
  accumulateTetQuality(s, &cs, queried);
  accumulateTetQuality(s, &cs, read, nullptr, &vm);
  EXPECT_EQ(read.tets, queried.tets);
  EXPECT_EQ(read.etaM.mean(), queried.etaM.mean());
  EXPECT_EQ(read.etaM.min(), queried.etaM.min());
  EXPECT_EQ(read.muM.count(), queried.muM.count());
  EXPECT_EQ(read.muM.mean(), queried.muM.mean());
  EXPECT_EQ(read.muM.max(), queried.muM.max());
  EXPECT_EQ(read.muMUser.mean(), queried.muMUser.mean());
}

TEST(TetQuality, ReadsTheImprovementsTensors) {
  checkReportFromImprovementTensors(gradedAnisotropic());
  checkReportFromImprovementTensors(gradedIsotropic());
}

}  // namespace

namespace {

// The bound behind VertexMetrics::SliverAngles: η³ ≤ 2 sin²θ for every dihedral angle θ.
TEST(SliverAngles, MeanRatioBoundsEveryDihedralAngle) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double tightest = 0;  // largest η³ / (2 sin²θ_min) seen
  for (int k = 0; k < 20000; ++k) {
    Vec3 p[4];
    for (auto& q : p) q = Vec3(u(rng), u(rng), u(rng));
    if (k % 2) p[3] = 0.5 * (p[0] + p[1]) + 0.1 * (p[3] - p[2]);
    const double eta = std::abs(tetMeanRatio(p[0], p[1], p[2], p[3]));
    const DihedralRange r = tetDihedralRange(p[0], p[1], p[2], p[3]);
    const double s = std::min(std::sin(r.minDeg * kDegToRad), std::sin(r.maxDeg * kDegToRad));
    if (!(s > 0)) continue;
    EXPECT_LE(eta * eta * eta, 2 * s * s * (1 + 1e-12)) << k;
    tightest = std::max(tightest, eta * eta * eta / (2 * s * s));
  }
  EXPECT_GT(tightest, 0.3);  // the bound is not vacuous on these tets
}

}  // namespace

// VertexMetrics::etaGradient (the ascent smoothing's gradient) agrees with central
// differences of η_M = cbrt(scoreWith) in a graded anisotropic field and an isotropic one.
TEST(VertexMetrics, EtaGradientAgreesWithDifferences) {
  for (const CSAnalytic3d& cs : {gradedAnisotropic(), gradedIsotropic()}) {
    std::set<Triple> boundary;
    SolidTetMesh s = cubeSolid(5, boundary);
    refineVolume(s, cs);
    const improve3d::VertexMetrics vm(s.mesh, cs);
    int checked = 0;
    for (std::uint32_t k = 0; k < s.mesh.tetSlots() && checked < 200; k += 7) {
      const del3d::TetId t(k);
      if (!s.mesh.isAlive(t)) continue;
      const std::uint32_t* v = s.mesh.tetVertices(t);
      if (vm.score(v) < 1e-3) continue;
      const std::uint32_t moved = v[k % 4];
      Vec3 g;
      const double eta = vm.etaGradient(v, moved, g);
      EXPECT_NEAR(eta, std::cbrt(vm.score(v)), 1e-12);
      const Vec3 p = s.mesh.point(del3d::VertexId(moved));
      const double h = 1e-6 * (s.mesh.point(del3d::VertexId(v[(k + 1) % 4])) - p).norm();
      for (int d = 0; d < 3; ++d) {
        Vec3 a = p, b = p;
        a[d] += h;
        b[d] -= h;
        const double fd = (std::cbrt(vm.scoreWith(v, moved, a)) - std::cbrt(vm.scoreWith(v, moved, b))) / (2 * h);
        EXPECT_NEAR(g[d], fd, 1e-5 * std::max(1.0, g.norm())) << k << " " << d;
      }
      ++checked;
    }
    EXPECT_GT(checked, 50);
  }
}
