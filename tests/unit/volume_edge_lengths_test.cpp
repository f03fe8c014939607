// Tests of edgeLengths (mesher/volume/EdgeLengths.h): each edge counted once.
#include <gtest/gtest.h>

#include <cmath>

#include "mesher/volume/EdgeLengths.h"

using namespace aniso;

TEST(EdgeLengths, UnitTetrahedronAndItsFaces) {
  VolumeMesh v;
  v.surface.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  v.surface.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  v.tets = {{0, 1, 2, 3}};
  const EdgeLengthRange s = edgeLengths(v.surface), t = edgeLengths(v);
  EXPECT_EQ(s.edges, 6u);  // 12 triangle sides, 6 distinct edges
  EXPECT_EQ(t.edges, 6u);
  EXPECT_DOUBLE_EQ(t.min, 1.0);
  EXPECT_DOUBLE_EQ(t.max, std::sqrt(2.0));
  EXPECT_NEAR(t.mean, (3 + 3 * std::sqrt(2.0)) / 6, 1e-15);
  EXPECT_DOUBLE_EQ(s.max, t.max);
}

TEST(EdgeLengths, EmptyMeshIsZero) {
  const EdgeLengthRange r = edgeLengths(SurfaceMesh{});
  EXPECT_EQ(r.edges, 0u);
  EXPECT_EQ(r.max, 0.0);
}
