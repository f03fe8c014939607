// Tests of the vertex removal of the volume improvement (improve/VertexRemoval.h) on
// hand-made configurations, validated (checkSolid: validateSolidTetMesh and the kernel's
// validate) after each change.
#include <gtest/gtest.h>

#include <cmath>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/delaunay3d/Inserter.h"
#include "mesher/volume/improve/VertexRemoval.h"
#include "volume_refine_fixture.h"

using namespace aniso;
using namespace aniso::testing;
using del3d::TetId;
using del3d::VertexId;

namespace {

const CSAnalytic3d& unitSpace() {
  static const CSAnalytic3d cs(Box3(Vec3(-3, -3, -3), Vec3(3, 3, 3)), [](const Vec3&) { return Metric3d::isotropic(1); });
  return cs;
}

double worstEta(const SolidTetMesh& s, const improve3d::VertexMetrics& vm) {
  double w = 1e300;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k)
    if (s.mesh.isAlive(TetId(k))) w = std::min(w, vm.eta(s.mesh.tetVertices(TetId(k))));
  return w;
}

/// The unit cube meshed as box.brep at the defaults: corners 0..7, face centres 8..13 on
/// the surface (each face four triangles around its centre), one free inner point 14 at
/// `centre`, and the 24 tets joining it to the surface triangles.
SolidTetMesh boxWithCentre(const Vec3& centre, std::set<Triple>& boundary) {
  std::vector<Vec3> pts;
  for (int c = 0; c < 8; ++c) pts.emplace_back(c & 1, (c >> 1) & 1, (c >> 2) & 1);
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      Vec3 p(0.5, 0.5, 0.5);
      p[axis] = side;
      pts.push_back(p);
    }
  pts.push_back(centre);
  std::vector<std::array<int, 4>> tets;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int fc = 8 + 2 * axis + side;
      // the face's corners in cyclic order
      std::vector<int> ring;
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for (const auto& [a, b] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}}) {
        int c = side << axis;
        c |= a << u;
        c |= b << w;
        ring.push_back(c);
      }
      for (int k = 0; k < 4; ++k) tets.push_back({ring[k], ring[(k + 1) % 4], fc, 14});
    }
  SolidTetMesh s = solidFrom(pts, tets, boundary);
  s.node[pv(14).index] = -1;  // the inner point is free
  return s;
}

}  // namespace

TEST(VertexRemoval, BoxCentreGoesDelaunayFillsTheBoundaryNodesAlone) {
  std::set<Triple> boundary;
  SolidTetMesh s = boxWithCentre(Vec3(0.5, 0.5, 0.5), boundary);
  ASSERT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  improve3d::VertexMetrics vm(s.mesh, unitSpace());
  EXPECT_NEAR(worstEta(s, vm), 0.8, 1e-12);  // 3 / 3.75: each tet on a right triangle
  improve3d::VertexRemoval removal(s, vm);
  std::vector<TetId> created;
  ASSERT_TRUE(removal.tryRemove(pv(14), {}, created));
  EXPECT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  EXPECT_FALSE(s.mesh.vertexTet(pv(14)).valid());
  // 8 corner tets (regular), 12 edge tets and 4 in the octahedron of the face centres,
  // each with five edges of √½ and one of 1: η = 6/7
  EXPECT_EQ(s.mesh.numTets(), 24u);
  EXPECT_EQ(created.size(), 24u);
  EXPECT_NEAR(worstEta(s, vm), 6.0 / 7.0, 1e-9);
  EXPECT_NEAR(meshVolume(s.mesh), 1.0, 1e-12);
}

TEST(VertexRemoval, RunRemovesOnlyPoorStarsHeldByTheBoundary) {
  std::set<Triple> boundary;
  improve3d::VertexRemovalOptions o;
  {
    // a star better than candidateBelow is not a candidate
    SolidTetMesh s = boxWithCentre(Vec3(0.5, 0.5, 0.5), boundary);
    improve3d::VertexMetrics vm(s.mesh, unitSpace());
    improve3d::VertexRemoval removal(s, vm);
    std::vector<TetId> created;
    o.candidateBelow = 0.79;
    EXPECT_EQ(removal.run(o, created).removed, 0u);
    EXPECT_EQ(s.mesh.numTets(), 24u);
    // a poor one is (the centre off-centre: worst below 0.8), with the Delaunay fill
    o.candidateBelow = 0.8;
    s = boxWithCentre(Vec3(0.45, 0.55, 0.6), boundary);
    improve3d::VertexMetrics vm2(s.mesh, unitSpace());
    improve3d::VertexRemoval removal2(s, vm2);
    const improve3d::VertexRemovalStats st = removal2.run(o, created);
    EXPECT_EQ(st.removed, 1u);
    EXPECT_EQ(st.byDelaunay, 1u);
    EXPECT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
    EXPECT_NEAR(worstEta(s, vm2), 6.0 / 7.0, 1e-9);
  }
  {
    // a star held by free vertices is not a candidate: heldShare above the share of fixed
    // vertices (here all of them are fixed: share 1)
    SolidTetMesh s = boxWithCentre(Vec3(0.45, 0.55, 0.6), boundary);
    improve3d::VertexMetrics vm(s.mesh, unitSpace());
    improve3d::VertexRemoval removal(s, vm);
    std::vector<TetId> created;
    o.heldShare = 1.01;
    EXPECT_EQ(removal.run(o, created).removed, 0u);
    EXPECT_FALSE(removal.tryRemove(pv(14), o, created));
    EXPECT_EQ(s.mesh.numTets(), 24u);
  }
}

TEST(VertexRemoval, GoodStarIsKeptEvenWhenAsked) {
  // the centre of an icosahedron: 20 near-regular tets; no tetrahedralisation of the
  // icosahedron without it comes close
  std::set<Triple> boundary;
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> pts;
  for (const double a : {-1.0, 1.0})
    for (const double b : {-g, g}) {
      pts.emplace_back(0, a, b);
      pts.emplace_back(a, b, 0);
      pts.emplace_back(b, 0, a);
    }
  pts.emplace_back(0, 0, 0);
  std::vector<std::array<int, 4>> tets;
  for (int i = 0; i < 12; ++i)
    for (int j = i + 1; j < 12; ++j)
      for (int k = j + 1; k < 12; ++k) {
        const double e = 2.0 + 1e-9;  // the icosahedron's edge
        if ((pts[i] - pts[j]).norm() < e && (pts[j] - pts[k]).norm() < e && (pts[i] - pts[k]).norm() < e)
          tets.push_back({i, j, k, 12});
      }
  ASSERT_EQ(tets.size(), 20u);
  SolidTetMesh s = solidFrom(pts, tets, boundary);
  s.node[pv(12).index] = -1;
  improve3d::VertexMetrics vm(s.mesh, unitSpace());
  improve3d::VertexRemoval removal(s, vm);
  improve3d::VertexRemovalOptions o;
  o.candidateBelow = 1.0;  // asked to try
  o.heldShare = 0;
  std::vector<TetId> created;
  EXPECT_FALSE(removal.tryRemove(pv(12), o, created));
  EXPECT_EQ(s.mesh.numTets(), 20u);
  EXPECT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
}

TEST(VertexRemoval, CrowdedPairGoesTogether) {
  // two free points near the box's centre (the refinement's crowding at the defaults):
  // removed as a group, down to the boundary nodes' 24 tets
  std::set<Triple> boundary;
  SolidTetMesh s = boxWithCentre(Vec3(0.5, 0.5, 0.55), boundary);
  del3d::Inserter ins(s.mesh);
  ASSERT_EQ(ins.insert(Vec3(0.45, 0.5, 0.3)).status, del3d::InsertStatus::Inserted);
  s.node.resize(s.mesh.numVertices(), -1);
  ASSERT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  const std::size_t before = s.mesh.numTets();
  improve3d::VertexMetrics vm(s.mesh, unitSpace());
  const double worstBefore = worstEta(s, vm);
  improve3d::VertexRemoval removal(s, vm);
  std::vector<TetId> created;
  const improve3d::VertexRemovalStats st = removal.run({}, created);
  EXPECT_TRUE(checkSolid(s, boundary).empty()) << joined(checkSolid(s, boundary));
  EXPECT_EQ(st.removed, 2u);
  EXPECT_EQ(st.byGroup, 1u);  // one at a time, the second's link is cospherical: no fill
  EXPECT_LT(worstBefore, 0.8);
  EXPECT_GT(before, 24u);
  EXPECT_EQ(s.mesh.numTets(), 24u);
  EXPECT_NEAR(worstEta(s, vm), 6.0 / 7.0, 1e-9);
  EXPECT_NEAR(meshVolume(s.mesh), 1.0, 1e-12);
}
