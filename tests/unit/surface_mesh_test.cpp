// SurfaceMesh::validate and edgeCounts: a closed consistently oriented surface passes with
// no open, non-manifold or misoriented edges; each kind of defect is reported.
#include <gtest/gtest.h>

#include <string>

#include "mesher/surface/SurfaceMesh.h"

using namespace aniso;

namespace {

/// The boundary of a tetrahedron, outward oriented, all on face 0.
SurfaceMesh tetrahedron() {
  SurfaceMesh m;
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}) m.addNode(p, NodeOn{});
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  m.triangleFace = {0, 0, 0, 0};
  return m;
}

bool mentions(const std::vector<std::string>& msgs, const std::string& what) {
  for (const std::string& s : msgs)
    if (s.find(what) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(SurfaceMesh, ClosedOrientedSurface) {
  const SurfaceMesh m = tetrahedron();
  EXPECT_TRUE(m.validate().empty());
  const SurfaceMesh::EdgeCounts c = m.edgeCounts();
  EXPECT_EQ(c.open, 0);
  EXPECT_EQ(c.nonManifold, 0);
  EXPECT_EQ(c.misoriented, 0);
}

TEST(SurfaceMesh, AddNodeRecordsTheEntity) {
  SurfaceMesh m;
  NodeOn on;
  on.kind = NodeOn::Kind::Edge;
  on.entity = 4;
  on.t = 0.25;
  EXPECT_EQ(m.addNode(Vec3(1, 2, 3), on), 0);
  EXPECT_EQ(m.addNode(Vec3(4, 5, 6), NodeOn{}), 1);
  EXPECT_EQ(m.nodeOn[0].kind, NodeOn::Kind::Edge);
  EXPECT_EQ(m.nodeOn[0].entity, 4);
  EXPECT_EQ(m.nodes[1], Vec3(4, 5, 6));
}

TEST(SurfaceMesh, OpenMisorientedNonManifoldEdges) {
  SurfaceMesh open = tetrahedron();
  open.triangles.pop_back();
  open.triangleFace.pop_back();
  EXPECT_EQ(open.edgeCounts().open, 3);
  EXPECT_TRUE(open.validate().empty());  // an open surface is structurally valid

  SurfaceMesh flipped = tetrahedron();
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  EXPECT_EQ(flipped.edgeCounts().misoriented, 3);
  EXPECT_EQ(flipped.edgeCounts().open, 0);

  SurfaceMesh fin = tetrahedron();
  fin.addNode(Vec3(-1, -1, 0), NodeOn{});
  fin.triangles.push_back({0, 1, 4});  // a fourth triangle on edge (0, 1), another face
  fin.triangleFace.push_back(1);
  EXPECT_EQ(fin.edgeCounts().nonManifold, 1);
  EXPECT_EQ(fin.edgeCounts().open, 2);
  EXPECT_TRUE(fin.validate().empty());  // three triangles on the edge, but from two faces
  fin.triangleFace.back() = 0;
  EXPECT_TRUE(mentions(fin.validate(), "edge (0, 1) is used by 3 triangles of face 1"));
}

TEST(SurfaceMesh, StructuralDefects) {
  SurfaceMesh m = tetrahedron();
  m.triangles.push_back({1, 3, 0});  // same nodes as triangle 1
  m.triangleFace.push_back(2);
  m.triangles.push_back({2, 2, 3});
  m.triangleFace.push_back(2);
  auto msgs = m.validate();
  EXPECT_TRUE(mentions(msgs, "triangle 4 has the same nodes as triangle 1")) << msgs.size();
  EXPECT_TRUE(mentions(msgs, "triangle 5 repeats node 2"));

  SurfaceMesh range = tetrahedron();
  range.triangles[2][1] = 9;
  EXPECT_TRUE(mentions(range.validate(), "triangle 2 refers to a node out of range"));
  range.triangles[2][1] = -1;
  EXPECT_TRUE(mentions(range.validate(), "triangle 2 refers to a node out of range"));

  SurfaceMesh sizes = tetrahedron();
  sizes.triangleFace.pop_back();
  sizes.nodeOn.pop_back();
  sizes.nodes[0].x() = std::nan("");
  msgs = sizes.validate();
  EXPECT_TRUE(mentions(msgs, "4 triangles but 3 triangle faces"));
  EXPECT_TRUE(mentions(msgs, "4 nodes but 3 node entities"));
  EXPECT_TRUE(mentions(msgs, "node 0 has non-finite coordinates"));
}
