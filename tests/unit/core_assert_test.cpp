// ANISO_ASSERT (mesher/core/Assert.h): in a build with ANISOMESH_ASSERTS (Debug, the sanitizer
// build) a violated precondition throws AssertionError naming file, line and condition, also
// from the kernels' accessors; in Release it is compiled out and its condition not evaluated.
#include <gtest/gtest.h>

#include <string>

#include "mesher/core/Assert.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/delaunay3d/TetMesh.h"

namespace aniso {
namespace {

TEST(CoreAssert, ThrowsWithFileLineAndCondition) {
  if (!kAssertsEnabled) GTEST_SKIP() << "ANISO_ASSERT is compiled out in this build";
  const int n = 3;
  int line = 0;
  try {
    line = __LINE__ + 1;
    ANISO_ASSERT(n < 2);
    FAIL() << "no exception";
  } catch (const AssertionError& e) {
    EXPECT_EQ(e.condition(), "n < 2");
    EXPECT_EQ(e.line(), line);
    EXPECT_NE(e.file().find("core_assert_test.cpp"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("core_assert_test.cpp:" + std::to_string(line) + ": precondition failed: n < 2"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(ANISO_ASSERT(n > 2));
}

TEST(CoreAssert, CompiledOutDoesNotEvaluateTheCondition) {
  if (kAssertsEnabled) GTEST_SKIP() << "ANISO_ASSERT is checked in this build";
  int calls = 0;
  ANISO_ASSERT(++calls > 5);
  EXPECT_EQ(calls, 0);
}

TEST(CoreAssert, Triangulation2dRejectsDeadAndOutOfRangeHandles) {
  if (!kAssertsEnabled) GTEST_SKIP() << "ANISO_ASSERT is compiled out in this build";
  Box2 box;
  box.add(Vec2(0, 0));
  box.add(Vec2(1, 1));
  del2d::Triangulation2d tri(box);
  const auto n = static_cast<std::uint32_t>(tri.triangleSlots());
  EXPECT_THROW(tri.vertex(del2d::TriId(n), 0), AssertionError);
  EXPECT_THROW(tri.neighbour(del2d::TriId(0), 3), AssertionError);
  EXPECT_THROW(tri.point(del2d::VertexId(static_cast<std::uint32_t>(tri.numVertices()))), AssertionError);
  const del2d::VertexId v = tri.addVertex(Vec2(0.5, 0.5));
  EXPECT_THROW(tri.createTriangle(v, v, tri.corners()[0]), AssertionError);
  tri.freeTriangle(del2d::TriId(0));
  EXPECT_THROW(tri.freeTriangle(del2d::TriId(0)), AssertionError);  // freed twice
  EXPECT_THROW(tri.triVertices(del2d::TriId(0)), AssertionError);   // a free slot
  EXPECT_NO_THROW(tri.nextFree(del2d::TriId(0)));
}

TEST(CoreAssert, TetMeshRejectsDeadAndOutOfRangeHandles) {
  if (!kAssertsEnabled) GTEST_SKIP() << "ANISO_ASSERT is compiled out in this build";
  del3d::TetMesh mesh;
  const del3d::VertexId a = mesh.addVertex(Vec3(0, 0, 0)), b = mesh.addVertex(Vec3(1, 0, 0)),
                        c = mesh.addVertex(Vec3(0, 1, 0)), d = mesh.addVertex(Vec3(0, 0, 1));
  EXPECT_THROW(mesh.createTet(a, b, c, del3d::VertexId(4)), AssertionError);
  const del3d::TetId t = mesh.createTet(a, b, d, c);
  EXPECT_THROW(mesh.adjacentCode(t, 4), AssertionError);
  EXPECT_THROW(mesh.setAdjacentCode(t, 0, del3d::faceCode(del3d::TetId(7), 1)), AssertionError);
  EXPECT_THROW(mesh.coords(del3d::VertexId(4)), AssertionError);
  mesh.freeTet(t);
  EXPECT_THROW(mesh.freeTet(t), AssertionError);
  EXPECT_THROW(mesh.vertex(t, 0), AssertionError);
}

}  // namespace
}  // namespace aniso
