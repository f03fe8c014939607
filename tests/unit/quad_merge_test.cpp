// Merging conversion (thesis alg. 4.4) with the front of eq. 4.4 and the odd-cycle split:
// the mesh stays valid, the boundary unchanged, and with even loops the region left after
// merging has an even number of triangles in every part.
#include <gtest/gtest.h>

#include "mesher/control/CSIdentity.h"
#include "mesher/quad/MergeConversion.h"
#include "quad_fixtures.h"

namespace {

using namespace aniso;
using namespace aniso::quad;
using quadtest::count;

TEST(QuadMerge, SquareBecomesMostlyQuads) {
  const FaceMesh fm = quadtest::triangleMesh({facetest::rectangle(0, 0, 1, 1)}, 0.05);
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(fm);
  const auto before = quadtest::snapshot(m);
  CSIdentity2d id(quadtest::Box2Of({facetest::rectangle(0, 0, 1, 1)}));
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, 0, 1, 1)}), 0.05);
  VertexMetrics metrics(m, *cs);
  const MergeStats st = mergeFront(m, metrics);
  quadtest::expectValid(m, before);
  EXPECT_EQ(st.triangles, count(m, 3));
  EXPECT_EQ(st.quads, count(m, 4));
  EXPECT_GT(count(m, 4), 0.9 * fm.triangles.size() / 2);
  EXPECT_EQ(count(m, 3) % 2, 0);
}

}  // namespace
