// checkSurfaceGeometry (mesher/volume/SurfaceGeometry.h): the repair stage's geometric
// postcondition finds folds and flat triangles on hand-made meshes (closure on closed
// solids is tested on a CAD model in tests/integration/surface_repair_test.cpp).
#include <gtest/gtest.h>

#include "mesher/volume/SurfaceGeometry.h"

using namespace aniso;

namespace {

SurfaceMesh twoTriangles(const Vec3& fourth) {
  SurfaceMesh m;
  const NodeOn on{NodeOn::Kind::Face, 0, 0, Vec2(0, 0)};
  m.addNode(Vec3(0, 0, 0), on);
  m.addNode(Vec3(1, 0, 0), on);
  m.addNode(Vec3(0.5, 1, 0), on);
  m.addNode(fourth, on);
  m.triangles = {{0, 1, 2}, {1, 0, 3}};
  m.triangleFace = {0, 0};
  return m;
}

}  // namespace

TEST(SurfaceGeometry, FlatQuadOfTwoTrianglesIsOk) {
  const SurfaceGeometryCheck c = checkSurfaceGeometry(Model{}, twoTriangles(Vec3(0.5, -1, 0)));
  EXPECT_TRUE(c.ok());
  EXPECT_TRUE(c.messages().empty());
}

TEST(SurfaceGeometry, TriangleTurnedOverItsNeighbourIsAFold) {
  // the second triangle's apex on the first one's side: its normal points down
  const SurfaceGeometryCheck c = checkSurfaceGeometry(Model{}, twoTriangles(Vec3(0.5, 0.2, 0)));
  EXPECT_EQ(c.foldedEdges, 1);
  EXPECT_FALSE(c.ok());
}

TEST(SurfaceGeometry, TriangleWithCollinearNodesIsFlat) {
  const SurfaceGeometryCheck c = checkSurfaceGeometry(Model{}, twoTriangles(Vec3(0.5, 0, 0)));
  EXPECT_GE(c.flatTriangles, 1);
  EXPECT_FALSE(c.ok());
  EXPECT_FALSE(c.messages().empty());
}

// A quad-dominant surface is closed when its triangles and quads together use every edge
// twice: a square pyramid whose base is a quad and a triangle (the triangles alone leave
// the quad's edges used once).
TEST(SurfaceGeometry, QuadsCountForClosure) {
  SurfaceMesh m;
  const NodeOn on{NodeOn::Kind::Face, 0, 0, Vec2(0, 0)};
  for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 1, 0), Vec3(0.5, 0.5, 1)})
    m.addNode(p, on);
  m.quads = {{0, 4, 2, 1}};
  m.quadFace = {0};
  m.triangles = {{0, 3, 4}, {0, 1, 5}, {1, 2, 5}, {2, 4, 5}, {4, 3, 5}, {3, 0, 5}};
  m.triangleFace = {0, 1, 2, 3, 3, 4};
  Model model;
  model.faces.resize(5);
  model.shells.push_back({});
  for (int f = 0; f < 5; ++f) model.shells[0].faces.push_back({f, false});
  model.shells[0].closed = true;
  model.solids.push_back({"pyramid", 0, {}, {}, 0});
  EXPECT_EQ(checkSurfaceGeometry(model, m).openEdges, 0);
  m.quads.clear();  // without the quad the base is open along its three edges and the diagonal
  m.quadFace.clear();
  EXPECT_EQ(checkSurfaceGeometry(model, m).openEdges, 4);
}

// Near a CAD edge the chords of two faces can pass through each other (a wedge narrower
// than their sagitta): two triangles of faces 0 and 1 around an edge node, the second's
// far edge piercing the first. The same pair bent apart along their common edge is fine,
// and so is a crossing around a node inside a face (folds there are the fold check's).
TEST(SurfaceGeometry, TrianglesCrossingNearAnEdgeAreFound) {
  const auto pair = [](const Vec3& c, const Vec3& d, NodeOn::Kind at) {
    SurfaceMesh m;
    const NodeOn face{NodeOn::Kind::Face, 0, 0, Vec2(0, 0)};
    m.addNode(Vec3(0, 0, 0), NodeOn{at, 0, 0, Vec2(0, 0)});
    m.addNode(Vec3(1, 0, 0), face);
    m.addNode(Vec3(0, 1, 0), face);
    m.addNode(c, face);
    m.addNode(d, face);
    m.triangles = {{0, 1, 2}, {0, 3, 4}};
    m.triangleFace = {0, 1};
    return m;
  };
  const SurfaceGeometryCheck crossed =
      checkSurfaceGeometry(Model{}, pair(Vec3(0.3, 0.3, -0.5), Vec3(0.3, 0.3, 0.5), NodeOn::Kind::Edge));
  EXPECT_EQ(crossed.crossingPairs, 1);
  ASSERT_EQ(crossed.crossingFaces.size(), 2u);
  EXPECT_FALSE(crossed.ok());
  EXPECT_FALSE(crossed.messages().empty());
  // the second triangle above the first (touching it only at the node): no crossing
  EXPECT_EQ(checkSurfaceGeometry(Model{}, pair(Vec3(0.3, 0.3, 0.5), Vec3(0.3, 0.6, 0.5), NodeOn::Kind::Edge)).crossingPairs, 0);
  // lying in the first one's plane, inside it: a node strictly inside the other counts
  EXPECT_EQ(checkSurfaceGeometry(Model{}, pair(Vec3(0.2, 0.1, 0), Vec3(0.1, 0.2, 0), NodeOn::Kind::Vertex)).crossingPairs, 1);
  // around a node inside a face: not looked at
  EXPECT_EQ(checkSurfaceGeometry(Model{}, pair(Vec3(0.3, 0.3, -0.5), Vec3(0.3, 0.3, 0.5), NodeOn::Kind::Face)).crossingPairs, 0);
}
