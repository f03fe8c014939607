// The surface's problems by CAD face (mesher/pipeline/RunProblems.h): a face not meshed is
// Failed, a face whose refinement stopped at its bound and a face the repair collapsed are
// Notes, each named by its 1-based id.
#include <gtest/gtest.h>

#include "mesher/pipeline/RunProblems.h"
#include "tests/unit/contour_test_models.h"

namespace aniso::test {
namespace {

TEST(SurfaceProblems, FailedLimitedAndCollapsedFacesAreNamed) {
  ModelBuilder b;
  for (int f = 0; f < 4; ++f) b.face(xyPlane(), box(0, 0, 1, 1));
  SurfaceMeshResult r;
  r.faces.resize(4);
  r.faces[0].problems = {"boundary edge (node 1, node 2) could not be recovered"};
  r.faces[1].triangles = 10;
  r.faces[1].stats.insertionLimitReached = true;
  r.faces[2].triangles = 6;  // meshed, then merged away: none of its triangles is left
  r.faces[3].triangles = 2;  // meshed and kept
  r.mesh.nodes = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  r.mesh.triangles = {{0, 1, 2}};
  r.mesh.triangleFace = {1};
  r.mesh.triangles.push_back({0, 2, 1});
  r.mesh.triangleFace.push_back(3);
  const std::vector<Problem> ps = surfaceProblems(b.m, r);
  ASSERT_EQ(ps.size(), 3u);
  EXPECT_EQ(ps[0].code, "face-mesh");
  EXPECT_EQ(ps[0].severity, Severity::Failed);
  EXPECT_EQ(ps[0].entity.id, 1);
  EXPECT_EQ(ps[1].code, "refinement-limit");
  EXPECT_EQ(ps[1].severity, Severity::Note);
  EXPECT_EQ(ps[1].entity.id, 2);
  EXPECT_EQ(ps[2].code, "face-collapsed");
  EXPECT_EQ(ps[2].entity.id, 3);
}

}  // namespace
}  // namespace aniso::test
