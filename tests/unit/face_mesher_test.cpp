// Tests of meshFace (mesher/surface/FaceMesher.h): metric conformity and quality (unit
// square, AN1 of appendix A.1), holes, boundary recovery on a non-convex domain, seams and
// poles, invalid loops, determinism. Every mesh is checked with validateFaceMesh (exact
// boundary, ccw triangles, manifold edges) and by its area.
#include <gtest/gtest.h>

#include <numbers>

#include "mesher/core/Error.h"
#include "mesher/surface/FaceMesher.h"
#include "mesher/surface/face/ValidateFaceMesh.h"
#include "tests/unit/face_mesher_fixtures.h"

using namespace aniso;
using namespace facetest;

namespace {

Box2 boxOf(double x0, double y0, double x1, double y1) {
  Box2 b;
  b.add(Vec2(x0, y0));
  b.add(Vec2(x1, y1));
  return b;
}

#define EXPECT_FACE_VALID(res, boundary)                                     \
  do {                                                                       \
    EXPECT_TRUE((res).ok()) << joined((res).problems);                       \
    const auto problems_ = face::validateFaceMesh((res).mesh, (boundary));   \
    EXPECT_TRUE(problems_.empty()) << joined(problems_);                     \
  } while (0)

TEST(FaceMesher, UnitSquareIsotropicIsAUnitMesh) {
  const double h = 0.05;
  const auto cs = isotropicSpace(boxOf(0, 0, 1, 1), h);
  const FaceBoundary b = polygonBoundary({rectangle(0, 0, 1, 1)}, h);
  const FaceMeshResult res = meshFace(b, *cs);
  EXPECT_FACE_VALID(res, b);
  EXPECT_NEAR(meshArea(res.mesh), 1.0, 1e-12);
  EXPECT_EQ(res.stats.boundaryNodes, 80);
  EXPECT_GT(res.stats.insertedInner, 100);
  std::size_t inRange = 0;
  const QualityStats mu = edgeLengthStats(res.mesh, *cs, 0.6, 1.5, &inRange);
  EXPECT_GE(static_cast<double>(inRange), 0.97 * static_cast<double>(mu.count()));
  EXPECT_NEAR(mu.mean(), 1.0, 0.1);
  const QualityStats eta = meanRatioStats(res.mesh, *cs);
  EXPECT_GE(eta.mean(), 0.9);
  EXPECT_GT(eta.min(), 0.3);
  // About 1 / (√3/4 h²) ≈ 924 triangles for a unit mesh.
  EXPECT_GT(res.mesh.triangles.size(), 700u);
  EXPECT_LT(res.mesh.triangles.size(), 1300u);
}

TEST(FaceMesher, An1FollowsTheAnisotropicMetric) {
  // k = 2: h1 = 0.02, h2 from 0.0202 down to 0.0002 at u = 2 (anisotropy 100). Larger k
  // make the needles near u = 2 span a larger part of the h2 gradient (h2 ∝ 2.02 − u does
  // not scale with k), where no triangle can follow the metric closely.
  const auto cs = an1Space(2);
  const FaceBoundary b = metricBoundary({rectangle(0, 0, 2, 1)}, *cs);
  const FaceMeshResult res = meshFace(b, *cs);
  EXPECT_FACE_VALID(res, b);
  EXPECT_NEAR(meshArea(res.mesh), 2.0, 1e-12);
  const QualityStats eta = meanRatioStats(res.mesh, *cs);
  const QualityStats mu = edgeLengthStats(res.mesh, *cs);
  EXPECT_GE(eta.mean(), 0.9) << "eta stddev " << eta.stddev();
  EXPECT_NEAR(mu.mean(), 1.0, 0.1) << "mu stddev " << mu.stddev();
  EXPECT_FALSE(res.stats.insertionLimitReached);
  // The thesis' AN1 (k = 1) has ~2.1e5 triangles (Table 4.4), so about 5.3e4 for k = 2.
  EXPECT_GT(res.mesh.triangles.size(), 40000u);
  EXPECT_LT(res.mesh.triangles.size(), 70000u);
}

TEST(FaceMesher, An1FromMetricExpressions) {
  // The same field given as the user's muParser expressions (eq. A.1).
  const CSAnalytic2d cs(boxOf(0, 0, 2, 1), "pi/6", "0.01*4", "4*(0.0101 - 0.005*u)");
  const FaceBoundary b = metricBoundary({rectangle(0, 0, 2, 1)}, cs, 1000);
  const FaceMeshResult res = meshFace(b, cs);
  EXPECT_FACE_VALID(res, b);
  EXPECT_NEAR(meshArea(res.mesh), 2.0, 1e-12);
  EXPECT_GE(meanRatioStats(res.mesh, cs).mean(), 0.87);
  EXPECT_NEAR(edgeLengthStats(res.mesh, cs).mean(), 1.0, 0.1);
}

TEST(FaceMesher, SquareWithCircularHole) {
  const double h = 0.04;
  const auto cs = isotropicSpace(boxOf(0, 0, 1, 1), h);
  const Polygon hole = circle(Vec2(0.5, 0.5), 0.2, 32, true);
  const FaceBoundary b = polygonBoundary({rectangle(0, 0, 1, 1), hole}, h);
  const FaceMeshResult res = meshFace(b, *cs);
  EXPECT_FACE_VALID(res, b);
  EXPECT_NEAR(meshArea(res.mesh), 1.0 - std::abs(signedArea(hole)), 1e-12);
  for (const auto& t : res.mesh.triangles) {
    const Vec2 c = (res.mesh.uv[t[0]] + res.mesh.uv[t[1]] + res.mesh.uv[t[2]]) / 3.0;
    ASSERT_FALSE(pointInPolygon(c, hole)) << "triangle inside the hole at " << c.transpose();
  }
  EXPECT_GE(meanRatioStats(res.mesh, *cs).mean(), 0.9);
}

TEST(FaceMesher, LShapeRecoversAMissingBoundaryEdge) {
  // The bottom side (0,0)-(2,0) is one segment; the reentrant corner (0.3, 0.3) and the
  // nodes of the side y = 0.3 lie inside its diametral circle, so it is not an edge of the
  // Delaunay triangulation of the boundary nodes and must be recovered by flips.
  const auto cs = isotropicSpace(boxOf(0, 0, 2, 2), 0.1);
  const Polygon lshape = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 0.3), Vec2(0.3, 0.3), Vec2(0.3, 2), Vec2(0, 2)};
  FaceBoundary b = polygonBoundary({lshape}, 0.1);
  // Keep the bottom side as a single segment: drop its intermediate nodes.
  auto& loop = b.loops[0];
  loop.erase(std::remove_if(loop.begin(), loop.end(),
                            [](const BoundaryNode& n) { return n.uv.y() == 0 && n.uv.x() > 0 && n.uv.x() < 2; }),
             loop.end());
  ASSERT_EQ(loop[1].uv, Vec2(2, 0));
  const FaceMeshResult res = meshFace(b, *cs);
  EXPECT_FACE_VALID(res, b);
  EXPECT_GT(res.stats.missingBoundaryEdges, 0);
  EXPECT_NEAR(meshArea(res.mesh), std::abs(signedArea(lshape)), 1e-12);
}

TEST(FaceMesher, SeamRectangleIsJustTheRectangle) {
  // A cylinder-like face: the left (u = 0) and right (u = 1) sides are the same model edge,
  // so their nodes are the same global nodes at different u.
  const double h = 0.05;
  const auto cs = isotropicSpace(boxOf(0, 0, 1, 1), h);
  FaceBoundary b;
  b.face = 3;
  std::vector<BoundaryNode> loop;
  int node = 1000;
  const int n = 20;
  std::vector<int> seam(n + 1);
  for (int j = 0; j <= n; ++j) seam[j] = 500 + j;
  for (int i = 0; i < n; ++i) loop.push_back({Vec2(static_cast<double>(i) / n, 0), i == 0 ? seam[0] : node++});
  for (int j = 0; j < n; ++j) loop.push_back({Vec2(1, static_cast<double>(j) / n), seam[j]});
  for (int i = n; i > 0; --i) loop.push_back({Vec2(static_cast<double>(i) / n, 1), i == n ? seam[n] : node++});
  for (int j = n; j > 0; --j) loop.push_back({Vec2(0, static_cast<double>(j) / n), seam[j]});
  b.loops.push_back(loop);
  const FaceMeshResult res = meshFace(b, *cs);
  EXPECT_FACE_VALID(res, b);
  EXPECT_NEAR(meshArea(res.mesh), 1.0, 1e-12);
  // Both copies of every seam node are boundary vertices with the shared global node.
  std::size_t seamVertices = 0;
  for (std::size_t k = 0; k < loop.size(); ++k) seamVertices += res.mesh.node[k] >= 500 && res.mesh.node[k] <= 500 + n;
  EXPECT_EQ(seamVertices, 2u * (n + 1));
  EXPECT_GE(meanRatioStats(res.mesh, *cs).mean(), 0.9);
}

TEST(FaceMesher, SphereLikeSeamAndPoles) {
  // [0, 2π] × [0, π] with both horizontal sides degenerate (poles: one global node each,
  // many (u, v)) and the vertical sides a seam. Planar metric, so only the topology of the
  // parametric boundary matters here.
  const double pi = std::numbers::pi;
  const auto cs = isotropicSpace(boxOf(0, 0, 2 * pi, pi), 0.2);
  FaceBoundary b;
  std::vector<BoundaryNode> loop;
  const int nu = 31, nv = 16;
  const int south = 0, north = 1;
  for (int i = 0; i < nu; ++i) loop.push_back({Vec2(2 * pi * i / nu, 0), south});
  for (int j = 0; j < nv; ++j) loop.push_back({Vec2(2 * pi, pi * j / nv), j == 0 ? south : 10 + j});
  for (int i = nu; i > 0; --i) loop.push_back({Vec2(2 * pi * i / nu, pi), north});
  for (int j = nv; j > 0; --j) loop.push_back({Vec2(0, pi * j / nv), j == nv ? north : 10 + j});
  b.loops.push_back(loop);
  const FaceMeshResult res = meshFace(b, *cs);
  EXPECT_FACE_VALID(res, b);
  EXPECT_NEAR(meshArea(res.mesh), 2 * pi * pi, 1e-9);
}

TEST(FaceMesher, CrossingLoopsAreReportedNotMeshed) {
  const auto cs = isotropicSpace(boxOf(-1, -1, 2, 2), 0.1);
  // Bow tie: (0,0) → (1,1) → (1,0) → (0,1): the first and third sides cross.
  const FaceBoundary bowTie = polygonBoundary({{Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)}}, 0.1);
  const FaceMeshResult r1 = meshFace(bowTie, *cs);
  EXPECT_FALSE(r1.ok());
  EXPECT_TRUE(r1.mesh.triangles.empty());
  ASSERT_FALSE(r1.problems.empty());
  EXPECT_NE(r1.problems.front().find("crosses boundary edge (node"), std::string::npos) << r1.problems.front();

  // A hole crossing the outer loop.
  const FaceBoundary crossingHole =
      polygonBoundary({rectangle(0, 0, 1, 1), circle(Vec2(1.03, 0.5), 0.2, 16, true)}, 0.1);
  const FaceMeshResult r2 = meshFace(crossingHole, *cs);
  EXPECT_FALSE(r2.ok());
  EXPECT_TRUE(r2.mesh.triangles.empty());
  ASSERT_FALSE(r2.problems.empty());
  EXPECT_NE(r2.problems.front().find("crosses boundary edge"), std::string::npos) << r2.problems.front();

  // A loop touching itself: a node on another side.
  const FaceBoundary touching =
      polygonBoundary({{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0.5, 0), Vec2(0, 1)}}, 0);
  const FaceMeshResult r3 = meshFace(touching, *cs);
  EXPECT_FALSE(r3.ok());
  EXPECT_TRUE(r3.mesh.triangles.empty());
  ASSERT_FALSE(r3.problems.empty());
  EXPECT_NE(r3.problems.front().find("passes through node 3"), std::string::npos) << r3.problems.front();

  // Two nodes at the same (u, v).
  const FaceBoundary repeated =
      polygonBoundary({{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)}}, 0);
  EXPECT_FALSE(meshFace(repeated, *cs).ok());

  // The outer loop clockwise (the face would be the unbounded outside).
  const FaceBoundary clockwise = polygonBoundary({{Vec2(0, 0), Vec2(0, 1), Vec2(1, 1), Vec2(1, 0)}}, 0.1);
  const FaceMeshResult r5 = meshFace(clockwise, *cs);
  EXPECT_FALSE(r5.ok());
  EXPECT_TRUE(r5.mesh.triangles.empty());

  // A hole given counter-clockwise.
  const FaceBoundary ccwHole = polygonBoundary({rectangle(0, 0, 1, 1), circle(Vec2(0.5, 0.5), 0.2, 16, false)}, 0.1);
  EXPECT_FALSE(meshFace(ccwHole, *cs).ok());
}

TEST(FaceMesher, InvalidInputIsTheFacesProblem) {
  const auto cs = isotropicSpace(boxOf(0, 0, 1, 1), 0.1);
  FaceBoundary b;
  b.face = 11;
  FaceMeshResult r = meshFace(b, *cs);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.problems.front().find("face 12"), std::string::npos) << r.problems.front();  // 1-based
  EXPECT_TRUE(r.mesh.triangles.empty());
  b.loops.push_back({BoundaryNode{Vec2(0, 0), 1}});
  r = meshFace(b, *cs);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.problems.front().find("loop 1"), std::string::npos) << r.problems.front();
}

TEST(FaceMesher, Deterministic) {
  const auto cs = an1Space(8);
  const FaceBoundary b = metricBoundary({rectangle(0, 0, 2, 1), circle(Vec2(1, 0.5), 0.2, 24, true)}, *cs, 1000);
  const FaceMeshResult r1 = meshFace(b, *cs);
  const FaceMeshResult r2 = meshFace(b, *cs);
  ASSERT_TRUE(r1.ok()) << joined(r1.problems);
  EXPECT_EQ(r1.mesh.uv, r2.mesh.uv);
  EXPECT_EQ(r1.mesh.node, r2.mesh.node);
  EXPECT_EQ(r1.mesh.triangles, r2.mesh.triangles);
  EXPECT_EQ(r1.stats.insertedInner, r2.stats.insertedInner);
  EXPECT_EQ(r1.stats.cancelledInsertions, r2.stats.cancelledInsertions);
}

TEST(FaceMesher, InnerAnglesCriterion) {
  const double h = 0.05;
  const auto cs = isotropicSpace(boxOf(0, 0, 1, 1), h);
  const FaceBoundary b = polygonBoundary({rectangle(0, 0, 1, 1), circle(Vec2(0.4, 0.6), 0.15, 20, true)}, h);
  FaceMesherOptions opt;
  opt.innerAnglesCriterion = true;
  const FaceMeshResult res = meshFace(b, *cs, opt);
  EXPECT_FACE_VALID(res, b);
  EXPECT_GE(meanRatioStats(res.mesh, *cs).mean(), 0.9);
  EXPECT_NEAR(edgeLengthStats(res.mesh, *cs).mean(), 1.0, 0.1);
}

}  // namespace
