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
