// splitSurfaceEdges (mesher/volume/SplitSurfaceEdges.h): the boundary Steiner points of
// the volume mesher's last recovery resort, put in the surface mesh on the CAD geometry.
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "contour_test_models.h"
#include "tests/unit/mesh_model_fixture.h"
#include "mesher/volume/SplitSurfaceEdges.h"

using namespace aniso;
using namespace aniso::test;

namespace {

double area(const SurfaceMesh& m) {
  double a = 0;
  for (const auto& t : m.triangles)
    a += 0.5 * (m.nodes[t[1]] - m.nodes[t[0]]).cross(m.nodes[t[2]] - m.nodes[t[0]]).norm();
  return a;
}

}  // namespace

TEST(SplitSurfaceEdges, KeepsTheShellClosedAndPutsNodesOnTheGeometry) {
  const double r = 1, h = 2;
  const Model model = cappedCylinder(r, h);
  SurfaceMesh mesh = meshModel(model, 0.5);
  ASSERT_EQ(mesh.edgeCounts().open, 0);
  const std::size_t nodes = mesh.nodes.size(), tris = mesh.triangles.size();
  // One edge inside a face (both ends on that face's interior or anywhere), one along a
  // model edge (both ends on the same model edge), one edge twice, one non-edge.
  std::array<int, 2> inner{-1, -1}, along{-1, -1};
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      const NodeOn &oa = mesh.nodeOn[a], &ob = mesh.nodeOn[b];
      if (inner[0] < 0 && oa.kind == NodeOn::Kind::Face && ob.kind == NodeOn::Kind::Face) inner = {a, b};
      if (along[0] < 0 && oa.kind == NodeOn::Kind::Edge && ob.kind == NodeOn::Kind::Edge && oa.entity == ob.entity &&
          !model.edges[oa.entity].seam)
        along = {a, b};
    }
  ASSERT_GE(inner[0], 0);
  ASSERT_GE(along[0], 0);
  const std::array<int, 2> request[] = {inner, along, {inner[1], inner[0]}, {0, 0}};
  const SplitStats st = splitSurfaceEdges(model, mesh, request);
  EXPECT_EQ(st.edgesSplit, 2);
  EXPECT_EQ(mesh.nodes.size(), nodes + 2);
  EXPECT_EQ(mesh.triangles.size(), tris + 4);  // every split edge had two triangles
  EXPECT_TRUE(mesh.validate().empty());
  const SurfaceMesh::EdgeCounts ec = mesh.edgeCounts();
  EXPECT_EQ(ec.open, 0);
  EXPECT_EQ(ec.nonManifold, 0);
  EXPECT_EQ(ec.misoriented, 0);
  // The new nodes lie on the cylinder (radius r) or on its caps, the one on the model
  // edge on that edge's circle.
  for (std::size_t n = nodes; n < mesh.nodes.size(); ++n) {
    const Vec3& p = mesh.nodes[n];
    const double radial = std::hypot(p.x(), p.y());
    const bool onSide = std::abs(radial - r) < 1e-9;
    const bool onCap = std::abs(p.z()) < 1e-9 || std::abs(p.z() - h) < 1e-9;
    EXPECT_TRUE(onSide || onCap) << p.transpose();
  }
  const NodeOn& onEdge = mesh.nodeOn[nodes + 1];
  EXPECT_TRUE(onEdge.kind == NodeOn::Kind::Edge || mesh.nodeOn[nodes].kind == NodeOn::Kind::Edge);
  // The split edges are gone, their halves are there.
  std::set<std::pair<int, int>> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  EXPECT_FALSE(edges.count(std::minmax(inner[0], inner[1])));
  EXPECT_FALSE(edges.count(std::minmax(along[0], along[1])));
}

TEST(SplitSurfaceEdges, SplitsEveryEdgeOfATriangle) {
  const Model model = unitSquare();
  SurfaceMesh mesh = meshModel(model, 0.25);
  const double before = area(mesh);
  const auto t = mesh.triangles[mesh.triangles.size() / 2];
  const std::array<int, 2> request[] = {{t[0], t[1]}, {t[1], t[2]}, {t[2], t[0]}};
  const SplitStats st = splitSurfaceEdges(model, mesh, request);
  EXPECT_EQ(st.edgesSplit, 3);
  EXPECT_TRUE(mesh.validate().empty());
  EXPECT_NEAR(area(mesh), before, 1e-12);  // planar: the same area, nothing folded
  // Every triangle still faces +z (the face's normal).
  for (const auto& tr : mesh.triangles) {
    const Vec3 n = (mesh.nodes[tr[1]] - mesh.nodes[tr[0]]).cross(mesh.nodes[tr[2]] - mesh.nodes[tr[0]]);
    EXPECT_GT(n.z(), 0);
  }
}

TEST(SplitSurfaceEdges, LongestEdgeOfATriangle) {
  SurfaceMesh m;
  m.addNode(Vec3(0, 0, 0), {});
  m.addNode(Vec3(3, 0, 0), {});
  m.addNode(Vec3(0, 1, 0), {});
  const std::array<int, 2> e = longestEdge(m, {0, 1, 2});
  EXPECT_EQ(e[0], 1);
  EXPECT_EQ(e[1], 2);
}

TEST(SplitSurfaceEdges, LeavesAnEdgeWholeWhoseMiddleIsANodeAlready) {
  // two edges of a fold over one point of the CAD place their middles on one point: the
  // Delaunay kernel cannot hold two nodes there (the solid failed with "surface node ...
  // coincides with node ..."); the second stays whole
  const Model model = unitSquare();
  const SurfaceMesh original = meshModel(model, 0.25);
  std::array<int, 2> inner{-1, -1};
  for (const auto& t : original.triangles)
    if (original.nodeOn[t[0]].kind == NodeOn::Kind::Face && original.nodeOn[t[1]].kind == NodeOn::Kind::Face) {
      inner = {t[0], t[1]};
      break;
    }
  ASSERT_GE(inner[0], 0);
  const std::array<int, 2> request[] = {inner};
  SurfaceMesh probe = original;  // where the middle goes
  ASSERT_EQ(splitSurfaceEdges(model, probe, request).edgesSplit, 1);
  SurfaceMesh mesh = original;
  mesh.addNode(probe.nodes.back(), probe.nodeOn.back());  // a node there already
  const std::size_t nodes = mesh.nodes.size();
  const SplitStats st = splitSurfaceEdges(model, mesh, request);
  EXPECT_EQ(st.edgesSplit, 0);
  EXPECT_EQ(mesh.nodes.size(), nodes);
  EXPECT_EQ(mesh.triangles, original.triangles);
}
