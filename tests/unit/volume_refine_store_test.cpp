// Tests of the refinement's data structures (mesher/volume/refine/): the per-vertex tensor
// store (VertexTensors.h: isotropic tensors kept as a scale, the scalar fast path of a tet,
// the eq. 2.18 metric of a tet and of an edge)
// and the bucket queue's compaction of stale entries (RefineQueue.h).
#include <gtest/gtest.h>

#include <vector>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/volume/refine/RefineQueue.h"
#include "mesher/volume/refine/VertexTensors.h"

using namespace aniso;
using del3d::TetId;
using del3d::VertexId;

namespace {

Box3 box() {
  Box3 b;
  b.add(Vec3(-1, -1, -1));
  b.add(Vec3(2, 2, 2));
  return b;
}

// Four points, the tet (0, 1, 2, 3) and a fifth vertex in no tet.
del3d::TetMesh oneTet(double x3) {
  del3d::TetMesh m;
  m.addVertex(Vec3(0, 0, 0));
  m.addVertex(Vec3(1, 0, 0));
  m.addVertex(Vec3(0, 1, 0));
  m.addVertex(Vec3(x3, 0, 1));
  m.addVertex(Vec3(5, 5, 5));
  const TetId t = m.createTet(VertexId(0), VertexId(1), VertexId(2), VertexId(3));
  for (std::uint32_t v = 0; v < 4; ++v) m.setVertexTet(VertexId(v), t);
  return m;
}

TEST(VolumeRefineStore, IsotropicTensorsAreScales) {
  // h = 0.5 where x < 0.5, an anisotropic metric beyond.
  const Metric3d aniso = Metric3d::fromDirections(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), 0.1, 0.2, 0.4);
  const CSAnalytic3d cs(box(), [&](const Vec3& p) { return p.x() < 0.5 ? Metric3d::isotropic(0.5) : aniso; });
  const del3d::TetMesh m = oneTet(0.0);
  const refine3d::VertexTensors vt(m, cs);
  EXPECT_TRUE(vt.isotropic(VertexId(0)));
  EXPECT_DOUBLE_EQ(vt.scale(VertexId(0)), 2.0);  // M = I / h
  EXPECT_FALSE(vt.isotropic(VertexId(1)));
  EXPECT_EQ(vt.scale(VertexId(1)), 0.0);
  EXPECT_TRUE((vt.at(VertexId(1)) - aniso.matrix()).norm() < 1e-15);
  EXPECT_TRUE((vt.at(VertexId(4)) - Mat3::Identity()).norm() == 0.0);  // in no tet: not queried
  const std::uint32_t tv[4] = {0, 1, 2, 3};
  double s = 0;
  EXPECT_FALSE(vt.tetScale(tv, s));  // vertex 1 is anisotropic
  const Mat3 mean = 0.25 * (3 * 2.0 * Mat3::Identity() + aniso.matrix());
  EXPECT_LT((vt.tetMetric(tv) - mean).norm(), 1e-14);
}

TEST(VolumeRefineStore, AllIsotropicTetHasAScalarMetric) {
  const CSAnalytic3d cs(box(), [](const Vec3& p) { return Metric3d::isotropic(0.5 + 0.25 * p.y()); });
  del3d::TetMesh m = oneTet(0.0);
  refine3d::VertexTensors vt(m, cs);
  const std::uint32_t tv[4] = {0, 1, 2, 3};
  double s = 0;
  ASSERT_TRUE(vt.tetScale(tv, s));
  EXPECT_NEAR(s, 0.25 * (2.0 + 2.0 + 1.0 / 0.75 + 2.0), 1e-14);
  EXPECT_LT((vt.tetMetric(tv) - s * Mat3::Identity()).norm(), 1e-14);
  // A vertex added with its metric already known is stored without a query.
  const VertexId v = m.addVertex(Vec3(0.2, 0.2, 0.2));
  vt.add(v, Metric3d::isotropic(0.125).matrix());
  EXPECT_DOUBLE_EQ(vt.scale(v), 8.0);
}

TEST(VolumeRefineStore, LengthMetricAveragesTheSizes) {
  // Eq. 2.18: the tet's metric is the inverse of the mean of the vertices' length tensors,
  // as the control space interpolates, not the mean of the tensors (which the finest vertex
  // rules: sizes 0.1 and 0.4 give 0.16 by the tensors, 0.25 by eq. 2.18).
  const CSAnalytic3d iso(box(), [](const Vec3& p) { return Metric3d::isotropic(p.x() > 0.5 ? 0.4 : 0.1); });
  const del3d::TetMesh m = oneTet(0.0);
  const refine3d::VertexTensors vt(m, iso);
  const std::uint32_t tv[4] = {0, 1, 2, 3};  // sizes 0.1, 0.4, 0.1, 0.1
  double s = 0;
  ASSERT_TRUE(vt.tetLengthScale(tv, s));
  EXPECT_NEAR(1.0 / s, 0.25 * (0.1 + 0.4 + 0.1 + 0.1), 1e-14);
  EXPECT_LT((vt.tetLengthMetric(tv) - s * Mat3::Identity()).norm(), 1e-12);
  EXPECT_NEAR(1.0 / refine3d::edgeLengthScale(vt.scale(VertexId(0)), vt.scale(VertexId(1))), 0.25, 1e-14);
  EXPECT_NEAR(1.0 / (0.5 * (vt.scale(VertexId(0)) + vt.scale(VertexId(1)))), 0.16, 1e-14);

  // Anisotropic: the same axes, each size averaged on its own.
  const Metric3d fine = Metric3d::fromDirections(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), 0.1, 0.2, 1.0);
  const Metric3d coarse = Metric3d::fromDirections(Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(), 0.3, 0.2, 2.0);
  const CSAnalytic3d an(box(), [&](const Vec3& p) { return p.x() > 0.5 ? coarse : fine; });
  const refine3d::VertexTensors va(m, an);
  ASSERT_FALSE(va.tetLengthScale(tv, s));
  const Mat3 expected = Vec3(1 / 0.15, 1 / 0.2, 1 / 1.25).asDiagonal();
  EXPECT_LT((va.tetLengthMetric(tv) - expected).norm(), 1e-10);
  const Mat3 edge = Vec3(1 / 0.2, 1 / 0.2, 1 / 1.5).asDiagonal();
  EXPECT_LT((va.edgeLengthMetric(VertexId(0), VertexId(1)) - edge).norm(), 1e-10);
}

TEST(VolumeRefineStore, CompactionDropsOnlyStaleEntries) {
  del3d::TetMesh m;
  for (int i = 0; i < 4; ++i) m.addVertex(Vec3(i == 1, i == 2, i == 3));
  refine3d::RefineQueue q(0.57);
  // Enough tets for a compaction; every third one is destroyed and every fifth re-pushed
  // (its first entry stale).
  const std::size_t n = std::size_t{1} << 17;
  std::vector<TetId> tets;
  for (std::size_t k = 0; k < n; ++k) {
    const TetId t = m.createTet(VertexId(0), VertexId(1), VertexId(2), VertexId(3));
    tets.push_back(t);
    q.renew(t);
    q.push(t, 0.5 * static_cast<double>(k % 97) / 97);
  }
  std::size_t live = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (k % 3 == 0) {
      m.freeTet(tets[k]);
      continue;
    }
    if (k % 5 == 0) {
      q.renew(tets[k]);
      q.push(tets[k], 0.01);
    }
    ++live;
  }
  // An identical queue left uncompacted pops the same sequence.
  refine3d::RefineQueue copy = q;
  const std::size_t before = q.size();
  q.compactIfGrown(m);
  EXPECT_EQ(q.size(), live);
  EXPECT_LT(q.size(), before);
  refine3d::RefineQueue::Entry a, b;
  std::size_t popped = 0;
  while (q.pop(m, a)) {
    ASSERT_TRUE(copy.pop(m, b));
    EXPECT_EQ(a.tet, b.tet);
    EXPECT_EQ(a.q, b.q);
    ++popped;
  }
  EXPECT_FALSE(copy.pop(m, b));
  EXPECT_EQ(popped, live);
}

}  // namespace
