// Tests of meshSurfaces (mesher/pipeline/SurfaceMesher.h): what one failing face does to
// the others.
#include <gtest/gtest.h>

#include <algorithm>

#include "contour_test_models.h"
#include "mesher/pipeline/SurfaceMesher.h"

using namespace aniso;

TEST(SurfaceMesher, ADegenerateFaceIsLeftOutTheOthersAreMeshed) {
  // two squares sharing an edge; the second has no extent in (u, v) (a zero-area face as
  // some exporters write it): it is left out with its reason, the first is meshed
  Model m = test::twoSquares();
  m.faces[1].uvBounds = Box2{};
  SurfaceMesherInput in;
  in.model = &m;
  in.options.sizing.hmax = 0.2;
  in.options.threads = 1;
  const SurfaceMeshResult r = meshSurfaces(in);
  EXPECT_TRUE(r.faces[0].problems.empty());
  ASSERT_EQ(r.faces[1].problems.size(), 1u);
  EXPECT_NE(r.faces[1].problems[0].find("no extent"), std::string::npos) << r.faces[1].problems[0];
  EXPECT_EQ(r.faces[1].problems[0].rfind("face 2", 0), std::string::npos);  // the face is named once, by the caller
  ASSERT_FALSE(r.mesh.triangles.empty());
  EXPECT_TRUE(std::all_of(r.mesh.triangleFace.begin(), r.mesh.triangleFace.end(), [](int f) { return f == 0; }));
}
