// edgePoint (mesher/model/EdgePoint.h): the node of a CAD edge lies where its faces meet.
#include <gtest/gtest.h>

#include "contour_test_models.h"
#include "mesher/model/EdgePoint.h"

namespace aniso {
namespace {

/// The y axis from (0,0,0) to (0,1,0) between the planes z = 0 (uv = xy) and x = 0
/// (uv = yz); the 3D curve is shifted by `offset` along z, the second pcurve by `skew` in v.
Model corner(double offset, double skew) {
  test::ModelBuilder b;
  const int v0 = b.vertex({0, 0, 0}), v1 = b.vertex({0, 1, 0});
  const int floor = b.face(test::xyPlane(), {{-10, -10}, {10, 10}});
  const int wall = b.face(std::make_shared<PlaneSurface>(Vec3::Zero(), Vec3::UnitY(), Vec3::UnitZ(), -10, 10, -10, 10),
                          {{-10, -10}, {10, 10}});
  const int e = b.edge(v0, v1, std::make_shared<Line3d>(Vec3(0, 0, offset), Vec3(0, 1, offset)), 0, 1);
  b.pcurve(e, floor, std::make_shared<Line2d>(Vec2(0, 0), Vec2(0, 1)));
  b.pcurve(e, wall, std::make_shared<Line2d>(Vec2(0, skew), Vec2(1, skew)));
  b.m.faces[floor].tolerance = b.m.faces[wall].tolerance = 1e-7;
  return b.m;
}

TEST(EdgePoint, ACurveWithinTheToleranceIsKept) {
  const Model m = corner(5e-8, 0);
  EXPECT_NEAR(edgePoint(m, 0, 0.5).z(), 5e-8, 1e-15);
}

TEST(EdgePoint, ACurveStrayingFromFacesThatAgreeGivesWayToThem) {
  const Model m = corner(1e-3, 0);  // 10^4 tolerances off both planes
  const Vec3 p = edgePoint(m, 0, 0.25);
  EXPECT_NEAR(p.x(), 0, 1e-12);
  EXPECT_NEAR(p.y(), 0.25, 1e-12);
  EXPECT_NEAR(p.z(), 0, 1e-12);
}

TEST(EdgePoint, FacesThatDisagreeLeaveTheCurve) {
  const Model m = corner(1e-3, 2e-3);  // the wall's pcurve is 2e-3 above the floor's
  EXPECT_NEAR(edgePoint(m, 0, 0.25).z(), 1e-3, 1e-15);
}

TEST(EdgePoint, AnEdgeOnOneFaceKeepsItsCurve) {
  Model m = corner(1e-3, 0);
  m.edges[0].pcurves.pop_back();
  EXPECT_NEAR(edgePoint(m, 0, 0.25).z(), 1e-3, 1e-15);
}

}  // namespace
}  // namespace aniso
