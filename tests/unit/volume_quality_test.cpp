// Tests of the tetrahedron quality measures (mesher/volume/TetQuality.h) and of the
// volume control space (mesher/volume/VolumeControlSpace.h).
#include <gtest/gtest.h>

#include <cmath>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/core/Error.h"
#include "mesher/volume/TetQuality.h"
#include "mesher/volume/VolumeControlSpace.h"
#include "volume_refine_fixture.h"

using namespace aniso;
using namespace aniso::testing;

namespace {

const Vec3 kA(0, 0, 0), kB(1, 0, 0), kC(0.5, std::sqrt(3.0) / 2, 0), kD(0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3));

TEST(TetQuality, RegularAndCornerTets) {
  EXPECT_NEAR(tetMeanRatio(kA, kB, kC, kD), 1.0, 1e-12);
  EXPECT_NEAR(tetMeanRatio(kA, kC, kB, kD), -1.0, 1e-12);  // inverted
  const DihedralRange r = tetDihedralRange(kA, kB, kC, kD);
  const double regular = std::acos(1.0 / 3) * 180 / M_PI;  // 70.5288°
  EXPECT_NEAR(r.minDeg, regular, 1e-9);
  EXPECT_NEAR(r.maxDeg, regular, 1e-9);
  // the corner tet of a cube: three right angles at the corner edges, the others acos(1/√3)
  const DihedralRange c = tetDihedralRange(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1));
  EXPECT_NEAR(c.maxDeg, 90.0, 1e-9);
  EXPECT_NEAR(tetDihedralRange(kA, kC, kB, kD).minDeg, regular, 1e-9);  // orientation does not matter
  EXPECT_NEAR(c.minDeg, std::acos(1 / std::sqrt(3.0)) * 180 / M_PI, 1e-9);
  EXPECT_NEAR(tetMinDihedral(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)), c.minDeg, 1e-12);
  // a sliver: four nearly coplanar points on a square: two angles near 0, two near 180°
  const Vec3 s0(0, 0, 0), s1(1, 0, 0.01), s2(1, 1, 0), s3(0, 1, 0.01);
  const DihedralRange sl = tetDihedralRange(s0, s1, s2, s3);
  EXPECT_LT(sl.minDeg, 2.0);
  EXPECT_GT(sl.maxDeg, 178.0);
  // meshq.py's measure (values printed by the referee for these tets): 70.53, 54.74, 178.38
  EXPECT_NEAR(refereeMinDihedral(kA, kB, kC, kD), 70.53, 0.005);
  EXPECT_NEAR(refereeMinDihedral(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)), 54.74, 0.005);
  EXPECT_NEAR(refereeMinDihedral(s0, s1, s2, s3), 178.38, 0.005);
  // it never goes below the true range folded onto [θ, 180° − θ]
  EXPECT_GE(refereeMinDihedral(s0, s1, s2, s3), std::min(sl.minDeg, 180 - sl.maxDeg));
}

TEST(TetQuality, SummaryOfACube) {
  std::set<Triple> boundary;
  const SolidTetMesh s = cubeSolid(3, boundary);
  TetQualitySummary q;
  accumulateTetQuality(s, nullptr, q);
  EXPECT_EQ(q.tets, s.mesh.numTets());
  EXPECT_EQ(q.inverted, 0u);
  EXPECT_NEAR(q.volume, 1.0, 1e-12);
  EXPECT_EQ(q.meanRatio.count(), q.tets);
  EXPECT_GT(q.meanRatio.min(), 0.0);
  EXPECT_LE(q.meanRatio.max(), 1.0);
  EXPECT_EQ(q.etaM.count(), 0u);
  EXPECT_EQ(q.muM.count(), 0u);
  // with the identity metric, η_M = η and μ_M = the Euclidean edge lengths
  Box3 box;
  box.add(Vec3(0, 0, 0));
  box.add(Vec3(1, 1, 1));
  const CSAnalytic3d unit(box, [](const Vec3&) { return Metric3d::isotropic(0.5); });
  TetQualitySummary m;
  accumulateTetQuality(s, &unit, m);
  EXPECT_NEAR(m.etaM.mean(), q.meanRatio.mean(), 1e-12);
  // Euler for a tetrahedralized ball: V − E + F − T = 1
  std::size_t faces = 0, verts = 0;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k)
    if (s.mesh.isAlive(del3d::TetId(k)))
      for (int i = 0; i < 4; ++i) faces += s.mesh.neighbour(del3d::TetId(k), i).valid() ? 1 : 2;
  for (std::uint32_t v = 0; v < s.mesh.numVertices(); ++v) verts += s.mesh.vertexTet(del3d::VertexId(v)).valid();
  EXPECT_EQ(static_cast<long>(verts) - static_cast<long>(m.muM.count()) + static_cast<long>(faces / 2) -
                static_cast<long>(q.tets),
            1);
  TetQualitySummary twice = q;
  twice.merge(q);
  EXPECT_EQ(twice.tets, 2 * q.tets);
  EXPECT_NEAR(twice.volume, 2.0, 1e-12);
}

// A model with one solid bounded by one shell of 6 faces, and the surface mesh of the cube
// with triangles of size about 1/n; on the face x = 0 the grid has mi × mj cells (default
// 2n × 2n: finer; mi ≠ mj: stretched triangles).
struct CubeModel {
  Model model;
  SurfaceMesh surface;
};

CubeModel cubeModel(int n, int mi = 0, int mj = 0) {
  CubeModel c;
  c.model.faces.resize(6);
  c.model.shells.resize(1);
  for (int f = 0; f < 6; ++f) c.model.shells[0].faces.push_back(FaceUse{f, false});
  c.model.solids.push_back(ModelSolid{"cube", 0, {}, {}});
  c.model.bbox.add(Vec3(0, 0, 0));
  c.model.bbox.add(Vec3(1, 1, 1));
  // each face its own grid (nodes not shared: enough for the metric)
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side <= 1; ++side) {
      const int face = 2 * axis + side;
      const bool special = axis == 0 && side == 0;
      const int ni = special ? (mi > 0 ? mi : 2 * n) : n, nj = special ? (mj > 0 ? mj : 2 * n) : n;
      const int base = static_cast<int>(c.surface.nodes.size());
      for (int i = 0; i <= ni; ++i)
        for (int j = 0; j <= nj; ++j) {
          Vec3 p;
          p[axis] = side;
          p[(axis + 1) % 3] = double(i) / ni;
          p[(axis + 2) % 3] = double(j) / nj;
          c.surface.addNode(p, NodeOn{});
        }
      for (int i = 0; i < ni; ++i)
        for (int j = 0; j < nj; ++j) {
          const int a = base + i * (nj + 1) + j, b = a + (nj + 1);
          c.surface.triangles.push_back({a, b, b + 1});
          c.surface.triangles.push_back({a, b + 1, a + 1});
          c.surface.triangleFace.push_back(face);
          c.surface.triangleFace.push_back(face);
        }
    }
  return c;
}

TEST(VolumeControlSpace, SurfaceSizesGradedIntoTheVolume) {
  const CubeModel c = cubeModel(8);
  SizingParameters p;
  p.hmaxRel = 0.3;  // h_max ≈ 0.52
  p.gradation = 2.0;
  const auto cs = buildVolumeControlSpace(c.model, c.surface, 0, p, nullptr);
  auto h = [&](const Vec3& x) { return cs->getMetric(x).axes().lengths; };
  // near the faces: the surface triangles' legs (1/8, and 1/16 on x = 0), isotropic
  const Vec3 nearFace = h(Vec3(0.98, 0.5, 0.5));
  EXPECT_NEAR(nearFace.minCoeff(), 0.125, 0.04);
  // right isosceles triangles: their simplex metric has lengths 0.82 and 1.41 of the legs
  EXPECT_LT(nearFace.maxCoeff() / nearFace.minCoeff(), 1.8);
  EXPECT_NEAR(h(Vec3(0.01, 0.5, 0.5)).minCoeff(), 0.0625, 0.02);
  // the interior grows but stays graded: at most h_max, larger than near the faces
  const Vec3 centre = h(Vec3(0.5, 0.5, 0.5));
  EXPECT_LE(centre.maxCoeff(), 0.3 * std::sqrt(3.0) * (1 + 1e-9));
  EXPECT_GT(centre.minCoeff(), nearFace.minCoeff());
  // the user's source makes elements smaller inside it only
  UserSizing user;
  SizingSource src;
  src.kind = SizingSource::Kind::Point;
  src.a = Vec3(0.5, 0.5, 0.5);
  src.radius = 0.1;
  src.metric = Metric3d::isotropic(0.02);
  user.sources.push_back(src);
  const auto cs2 = buildVolumeControlSpace(c.model, c.surface, 0, p, &user);
  EXPECT_NEAR(cs2->getMetric(Vec3(0.5, 0.5, 0.5)).axes().lengths.maxCoeff(), 0.02, 1e-3);
  EXPECT_GT(cs2->getMetric(Vec3(0.98, 0.9, 0.9)).axes().lengths.minCoeff(), 0.08);
}

TEST(VolumeControlSpace, StretchedSurfaceTrianglesGiveAnAnisotropicVolumeMetric) {
  // x = 0: cells 1/32 along y, 1/8 along z (eq. 3.3: the surface metric with the normal
  // direction at the smaller in-plane length)
  const CubeModel c = cubeModel(4, 32, 8);
  SizingParameters p;
  p.anisotropy = 5;
  const auto cs = buildVolumeControlSpace(c.model, c.surface, 0, p, nullptr);
  const Metric3d m = cs->getMetric(Vec3(0.005, 0.5, 0.5));
  const MetricAxes<3> ax = m.axes();
  const double shortest = ax.lengths.minCoeff(), longest = ax.lengths.maxCoeff();
  EXPECT_GT(longest / shortest, 2.5);
  EXPECT_LE(longest / shortest, 5 * (1 + 1e-9));       // γ_a
  EXPECT_GT(std::abs(ax.directions.col(2).z()), 0.8);  // the long direction follows z
  // the normal (x) gets the short length, not the long one
  EXPECT_LT(m.lengthAlong(Vec3::UnitX()), 1.5 * shortest);
  EXPECT_LT(shortest, 0.06);
  // the same grid with square cells gives an isotropic metric there
  const auto iso = buildVolumeControlSpace(cubeModel(4, 16, 16).model, cubeModel(4, 16, 16).surface, 0, p, nullptr);
  const MetricAxes<3> ai = iso->getMetric(Vec3(0.005, 0.5, 0.5)).axes();
  EXPECT_LT(ai.lengths.maxCoeff() / ai.lengths.minCoeff(), 1.8);
}

TEST(VolumeControlSpace, NoTrianglesIsAnError) {
  CubeModel c = cubeModel(2);
  c.surface.triangleFace.assign(c.surface.triangles.size(), 7);  // no face of the solid
  c.model.faces.resize(8);
  EXPECT_THROW(buildVolumeControlSpace(c.model, c.surface, 0, SizingParameters{}, nullptr), MeshingError);
}

}  // namespace
