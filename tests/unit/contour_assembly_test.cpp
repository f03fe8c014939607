// addFaceMesh: interior nodes, orientation of reversed faces, pole triangles dropped, bad
// input rejected; and the whole chain discretizeEdges → faceBoundary → meshFace →
// addFaceMesh on closed analytic shells (sphere with poles and seam, capped cylinder),
// which must give a closed, consistently outward-oriented SurfaceMesh.
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

#include "contour_test_models.h"
#include "mesher/core/Error.h"
#include "mesher/surface/ContourDiscretization.h"
#include "mesher/surface/FaceMesher.h"

using namespace aniso;
using namespace aniso::test;

namespace {

struct Boundaries {
  std::vector<std::unique_ptr<CSAnalytic2d>> spaces;
  SurfaceMesh mesh;
  std::vector<EdgeDiscretization> edges;

  Boundaries(const Model& m, double h, double gMin = 0) {
    std::vector<const ControlSpace2d*> ptrs;
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      spaces.push_back(space(m, static_cast<int>(f), isotropic(h), gMin));
      ptrs.push_back(spaces.back().get());
    }
    edges = discretizeEdges(m, ptrs, {}, mesh);
  }
};

/// Signed volume enclosed by the triangles (positive for an outward-oriented closed mesh).
double volume(const SurfaceMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles) v += m.nodes[t[0]].dot(m.nodes[t[1]].cross(m.nodes[t[2]])) / 6;
  return v;
}

/// Meshes every face of the model and assembles the surface mesh.
SurfaceMesh meshAll(const Model& m, double h, double gMin) {
  Boundaries r(m, h, gMin);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const FaceBoundary b = faceBoundary(m, static_cast<int>(f), r.edges, r.mesh);
    const FaceMeshResult fm = meshFace(b, *r.spaces[f]);
    EXPECT_TRUE(fm.ok()) << "face " << f + 1 << ": " << (fm.problems.empty() ? "" : fm.problems[0]);
    addFaceMesh(m, static_cast<int>(f), fm.mesh, r.mesh);
  }
  return r.mesh;
}

}  // namespace

TEST(ContourAssembly, InteriorNodesAndOrientation) {
  for (bool reversed : {false, true}) {
    const Model m = unitSquare(reversed);
    const Boundaries r(m, 5);  // one segment per edge
    const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
    ASSERT_EQ(b.loops[0].size(), 4u);
    FaceMesh fm;
    for (const BoundaryNode& n : b.loops[0]) {
      fm.uv.push_back(n.uv);
      fm.node.push_back(n.node);
    }
    fm.uv.push_back(Vec2(0.5, 0.5));
    fm.node.push_back(-1);
    for (int i = 0; i < 4; ++i) fm.triangles.push_back({i, (i + 1) % 4, 4});  // counter-clockwise in (u, v)
    SurfaceMesh mesh = r.mesh;
    addFaceMesh(m, 0, fm, mesh);
    ASSERT_EQ(mesh.nodes.size(), 5u);
    EXPECT_EQ(mesh.nodeOn[4].kind, NodeOn::Kind::Face);
    EXPECT_EQ(mesh.nodeOn[4].entity, 0);
    EXPECT_EQ(mesh.nodeOn[4].uv, Vec2(0.5, 0.5));
    EXPECT_NEAR((mesh.nodes[4] - Vec3(0.5, 0.5, 0)).norm(), 0, 1e-15);
    ASSERT_EQ(mesh.triangles.size(), 4u);
    EXPECT_EQ(mesh.triangleFace, std::vector<int>(4, 0));
    // Normal of the face: +z, or −z when reversed.
    for (const auto& t : mesh.triangles) {
      const Vec3 n = (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]);
      EXPECT_GT(reversed ? -n.z() : n.z(), 0);
    }
    EXPECT_TRUE(mesh.validate().empty());
    const SurfaceMesh::EdgeCounts c = mesh.edgeCounts();
    EXPECT_EQ(c.open, 4);
    EXPECT_EQ(c.misoriented, 0);
  }
}

TEST(ContourAssembly, PoleTrianglesAreDropped) {
  const Model m = sphere(1);
  const Boundaries r(m, 0.2, 0.04);
  const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
  FaceMesh fm;
  for (const BoundaryNode& n : b.loops[0]) {
    fm.uv.push_back(n.uv);
    fm.node.push_back(n.node);
  }
  // A fan from the first interior point to two consecutive boundary nodes on the south
  // pole (collapsed), and one to two distinct nodes (kept).
  fm.uv.push_back(Vec2(1, -1.2));
  fm.node.push_back(-1);
  const int inner = static_cast<int>(fm.uv.size()) - 1;
  int poleA = -1, ordinary = -1;
  for (int i = 0; i + 1 < static_cast<int>(b.loops[0].size()); ++i) {
    if (poleA < 0 && b.loops[0][i].node == 0 && b.loops[0][i + 1].node == 0) poleA = i;
    if (ordinary < 0 && b.loops[0][i].node != b.loops[0][i + 1].node) ordinary = i;
  }
  ASSERT_GE(poleA, 0);
  ASSERT_GE(ordinary, 0);
  fm.triangles = {{poleA, poleA + 1, inner}, {ordinary, ordinary + 1, inner}};
  SurfaceMesh mesh = r.mesh;
  const std::size_t before = mesh.nodes.size();
  addFaceMesh(m, 0, fm, mesh);
  EXPECT_EQ(mesh.nodes.size(), before + 1);
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangles[0][2], static_cast<int>(before));
  EXPECT_NEAR(mesh.nodes[before].norm(), 1.0, 1e-12);
}

TEST(ContourAssembly, RejectsInconsistentFaceMesh) {
  const Model m = unitSquare();
  SurfaceMesh mesh;
  FaceMesh fm;
  fm.uv = {Vec2(0, 0)};
  EXPECT_THROW(addFaceMesh(m, 0, fm, mesh), MeshingError);  // node entries missing
  fm.node = {3};
  EXPECT_THROW(addFaceMesh(m, 0, fm, mesh), MeshingError);  // node 3 does not exist
  fm.node = {-1};
  fm.triangles = {{0, 1, 2}};
  EXPECT_THROW(addFaceMesh(m, 0, fm, mesh), MeshingError);  // vertex 1 does not exist
  EXPECT_THROW(addFaceMesh(m, 4, FaceMesh{}, mesh), MeshingError);
}

TEST(ContourAssembly, SphereMeshIsClosedAndOutward) {
  // Poles with the model-relative g_min guard: the pole pieces must give the face mesher a
  // ring to fan from, or triangles fold onto each other around the pole.
  const Model m = sphere(1);
  for (double h : {0.1, 0.2, 0.5}) {
    SCOPED_TRACE("h = " + std::to_string(h));
    const SurfaceMesh mesh = meshAll(m, h, 1e-8);
    const std::vector<std::string> problems = mesh.validate();
    EXPECT_TRUE(problems.empty()) << problems.front();
    const SurfaceMesh::EdgeCounts c = mesh.edgeCounts();
    EXPECT_EQ(c.open, 0);
    EXPECT_EQ(c.nonManifold, 0);
    EXPECT_EQ(c.misoriented, 0);
    EXPECT_NEAR(volume(mesh), 4 * kPi / 3, 0.1 * 4 * kPi / 3);
    for (const Vec3& p : mesh.nodes) EXPECT_NEAR(p.norm(), 1.0, 1e-12);
  }
}

TEST(ContourAssembly, CappedCylinderMeshIsClosedAndOutward) {
  const Model m = cappedCylinder(1, 2);
  const SurfaceMesh mesh = meshAll(m, 0.25, 1e-4);
  EXPECT_TRUE(mesh.validate().empty()) << mesh.validate().front();
  const SurfaceMesh::EdgeCounts c = mesh.edgeCounts();
  EXPECT_EQ(c.open, 0);
  EXPECT_EQ(c.nonManifold, 0);
  EXPECT_EQ(c.misoriented, 0);
  EXPECT_NEAR(volume(mesh), 2 * kPi, 0.05 * 2 * kPi);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tr = mesh.triangles[t];
    const Vec3 n = (mesh.nodes[tr[1]] - mesh.nodes[tr[0]]).cross(mesh.nodes[tr[2]] - mesh.nodes[tr[0]]);
    if (mesh.triangleFace[t] == 1) {
      EXPECT_LT(n.z(), 0);  // the bottom cap faces down
    } else if (mesh.triangleFace[t] == 2) {
      EXPECT_GT(n.z(), 0);
    }
  }
}
