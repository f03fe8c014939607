// The face mesher's fold guard (mesher/surface/face/SurfaceLift.h), the unfolding step
// (UnfoldFace.h) and the flat-triangle pass (FlatTriangles.h) on a sphere: triangles that are counter-clockwise in (u, v) but turned
// over or standing across the surface in 3D, next to the pole and at a rim.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>

#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/Triangulation2d.h"
#include "mesher/delaunay/Validate2d.h"
#include "mesher/geometry/SphereSurface.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/surface/face/FlatTriangles.h"
#include "mesher/surface/face/SurfaceLift.h"
#include "mesher/surface/face/UnfoldFace.h"

using namespace aniso;
using face::LiftedPoint;
using face::SurfaceLift;

namespace {

constexpr double kHalfPi = 1.5707963267948966;

Box2 box(const Vec2& lo, const Vec2& hi) {
  Box2 b;
  b.add(lo);
  b.add(hi);
  return b;
}

/// The triangulation of the points (vertices 4, 5, ... after the box corners) with the edge
/// between vertices 6 and 7 flipped: the Delaunay diagonal replaced by the other one.
void triangulateWithOtherDiagonal(del2d::Triangulation2d& tri, std::initializer_list<Vec2> points) {
  for (const Vec2& p : points) ASSERT_EQ(del2d::insertPoint(tri, p).status, del2d::InsertStatus::Inserted);
  del2d::TriId t;
  int i = -1;
  ASSERT_TRUE(tri.findEdge(del2d::VertexId(7), del2d::VertexId(6), t, i) ||
              tri.findEdge(del2d::VertexId(6), del2d::VertexId(7), t, i));
  const del2d::FlipPlan plan = del2d::canFlip(tri, t, i);
  ASSERT_TRUE(plan.legal);
  del2d::flip(tri, plan);
}

bool hasEdge(const del2d::Triangulation2d& tri, int a, int b) {
  del2d::TriId t;
  int i = -1;
  return tri.findEdge(del2d::VertexId(a), del2d::VertexId(b), t, i) || tri.findEdge(del2d::VertexId(b), del2d::VertexId(a), t, i);
}

bool ccw(const Vec2& a, const Vec2& b, const Vec2& c) { return predicates::orient2d(a.data(), b.data(), c.data()) > 0; }

struct SphereFixture : ::testing::Test {
  SphereSurface sphere{Frame(), 1.0};
  SurfaceLift lift{&sphere};
  bool upright(const Vec2& a, const Vec2& b, const Vec2& c) const {
    return SurfaceLift::upright(lift.lift(a), lift.lift(b), lift.lift(c));
  }
};

TEST_F(SphereFixture, SmallTriangleIsUpright) {
  const Vec2 a(1.0, 0.2), b(1.1, 0.2), c(1.05, 0.3);
  ASSERT_TRUE(ccw(a, b, c));
  EXPECT_TRUE(upright(a, b, c));
  EXPECT_FALSE(upright(a, c, b));  // clockwise in (u, v): turned over
}

TEST_F(SphereFixture, TriangleWrappingAroundThePoleIsNotUpright) {
  // Counter-clockwise in (u, v) near the north pole, but it spans 140° of longitude there:
  // its chord faces into the sphere (a fold seen on a model's spherical faces).
  const Vec2 a(1.06, 1.25), b(3.51, 1.40), c(2.27, 1.44);
  ASSERT_TRUE(ccw(a, b, c));
  EXPECT_FALSE(upright(a, b, c));
}

TEST_F(SphereFixture, RimSliverStandingAcrossTheSurfaceIsNotUpright) {
  // Three points on one great circle (a meridian): the chord triangle contains the normal
  // direction, its own normal is tangent to the sphere.
  const Vec2 a(0.5, 0.0), b(0.5 + 1e-9, 0.1), c(0.5, 0.2);
  ASSERT_TRUE(ccw(a, c, b) || ccw(a, b, c));
  EXPECT_FALSE(upright(a, b, c));
  EXPECT_FALSE(upright(a, c, b));
}

TEST_F(SphereFixture, CollapsedAtThePoleAndLargeTrianglesAreExempt) {
  // Two corners at the pole (different u, one 3D point): no orientation, exempt.
  EXPECT_TRUE(upright(Vec2(0.0, kHalfPi), Vec2(1.0, 1.2), Vec2(1.0, kHalfPi)));
  // Corner normals 90° apart: a placeholder of the coarse triangulation, not tested.
  EXPECT_TRUE(upright(Vec2(0.0, 0.0), Vec2(kHalfPi, 0.0), Vec2(3.0, 0.1)));
}

TEST_F(SphereFixture, FlipUprightChecksBothNewTriangles) {
  // Quadrilateral a-b-d-c around the edge (b, c) near the pole.
  del2d::Triangulation2d tri(box(Vec2(-1, -1), Vec2(7, 2)));
  for (const Vec2& p : {Vec2(1.0, 1.2), Vec2(2.0, 1.2), Vec2(1.5, 1.45), Vec2(1.5, 1.0)})
    ASSERT_EQ(del2d::insertPoint(tri, p).status, del2d::InsertStatus::Inserted);
  int checked = 0;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const del2d::TriId t(k);
    if (!tri.isAlive(t)) continue;
    for (int i = 0; i < 3; ++i) {
      const del2d::FlipPlan plan = del2d::canFlip(tri, t, i);
      if (!plan.legal) continue;
      ++checked;
      EXPECT_EQ(lift.flipUpright(tri, plan),
                lift.upright(tri, plan.a, plan.b, plan.d) && lift.upright(tri, plan.a, plan.d, plan.c));
    }
  }
  EXPECT_GT(checked, 0);
}

TEST_F(SphereFixture, UnfoldFaceRemovesFoldsAndKeepsTheTriangulationValid) {
  // A Delaunay triangulation in (u, v) of points near the north pole whose triangles span
  // wide longitude ranges there: some are turned over.
  del2d::Triangulation2d tri(box(Vec2(-0.5, 0.9), Vec2(7.0, 1.6)));
  // The folded triangle of the previous test over the point below it (vertices 4–7 after
  // the box corners): flipping their common edge gives two upright triangles.
  // Delaunay in (u, v) takes the short diagonal; flipped to the long one: the fold.
  triangulateWithOtherDiagonal(tri, {Vec2(1.06, 1.25), Vec2(3.51, 1.40), Vec2(2.27, 1.44), Vec2(2.27, 1.2)});
  const auto before = face::notUpright(tri, lift);
  ASSERT_FALSE(before.empty());  // the configuration really is folded
  std::vector<std::uint8_t> fixed(tri.numVertices(), 0);
  for (const del2d::VertexId v : tri.corners()) fixed[v.index] = 1;
  const face::UnfoldFaceStats st = face::unfoldFace(tri, lift, fixed);
  EXPECT_EQ(st.foldedBefore, static_cast<int>(before.size()));
  EXPECT_EQ(st.foldedAfter, 0);
  EXPECT_GT(st.flips, 0);
  EXPECT_EQ(st.foldedAfter, static_cast<int>(face::notUpright(tri, lift).size()));
  EXPECT_TRUE(del2d::validate(tri).empty());
}

TEST_F(SphereFixture, FlatCapIsFlippedAway) {
  // A cap (a, b, c): c a hair above the middle of (a, b) near the equator, d below; made by
  // flipping the Delaunay diagonal (c, d) to (a, b).
  del2d::Triangulation2d tri(box(Vec2(-1, -1), Vec2(1.2, 1)));
  triangulateWithOtherDiagonal(tri, {Vec2(0, 0), Vec2(0.02, 0), Vec2(0.01, 0.00005), Vec2(0.01, -0.01)});
  std::vector<std::uint8_t> fixed(tri.numVertices(), 1);  // nothing may move: flips only
  const face::FlatTriangleStats st = face::removeFlatTriangles(tri, lift, fixed);
  // (The needles between the tiny quadrilateral and the far box corners count too.)
  EXPECT_LT(st.after, st.before);
  EXPECT_GE(st.flips, 1);
  EXPECT_TRUE(hasEdge(tri, 6, 7));  // the cap is gone
  EXPECT_TRUE(del2d::validate(tri).empty());
  EXPECT_LT(face::chordMeanRatio(lift.lift(Vec2(0, 0)), lift.lift(Vec2(0.02, 0)), lift.lift(Vec2(0.01, 0.00005))),
            face::kFlatMeanRatio);
}

}  // namespace
