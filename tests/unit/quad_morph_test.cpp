// The operators of the morphing conversion (thesis alg. 4.5) and of the pairing of the
// triangles left, one by one, each followed by the validators (structure, strictly convex
// counter-clockwise elements, boundary and area unchanged): side edges, upper-edge
// recovery, the seam, the transition seam and split, a whole morphing and mixed conversion, the chain re-quadrangulation,
// pole triangles and the removal of unused vertices.
#include <gtest/gtest.h>

#include <cmath>

#include "mesher/quad/ChainQuadrangulation.h"
#include "mesher/quad/FrontSeam.h"
#include "mesher/quad/MergeConversion.h"
#include "mesher/quad/PoleTriangles.h"
#include "mesher/quad/SideEdge.h"
#include "mesher/quad/TopEdgeRecovery.h"
#include "mesher/quad/TransitionSeam.h"
#include "mesher/quad/TransitionSplit.h"
#include "quad_fixtures.h"

namespace {

using namespace aniso;
using namespace aniso::quad;
using quadtest::count;

using Plate = quadtest::HolePlate;

/// The first front edge (triangle, edge) on the face boundary whose left end is a boundary
/// vertex with a straight (≈ π) region angle.
std::pair<int, int> straightBoundaryEdge(const QuadMesh2d& m, VertexMetrics& metrics) {
  for (int e = 0; e < m.numElements(); ++e)
    for (int k = 0; k < 3; ++k)
      if (m.adj[e][k] == kNone) {
        const RegionFan fan = regionFan(m, metrics, m.corners[e][k], e, true);
        if (!fan.closed && std::abs(fan.angle.back() - M_PI) < 0.05 && fan.triangles.size() >= 2) return {e, k};
      }
  return {kNone, kNone};
}

TEST(QuadSideEdge, BoundaryEdgeTakesAnEdgeNearTheBisector) {
  Plate p;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(p.fm);
  const auto snap = quadtest::snapshot(m);
  VertexMetrics metrics(m, *p.cs);
  const auto [e, k] = straightBoundaryEdge(m, metrics);
  ASSERT_NE(e, kNone);
  const int a = m.corners[e][k], b = m.corners[e][(k + 1) % 3];
  const SideEdge side = selectSideEdge(m, metrics, e, k, true, {});
  quadtest::expectValid(m, snap);
  ASSERT_FALSE(side.vertices.empty());
  EXPECT_FALSE(side.front);  // a straight boundary: α = π > 3π/4
  // The side edge leaves a within π/6 of the normal to the boundary (isotropic metric).
  const Vec2 base = m.uv[b] - m.uv[a], ray = m.uv[side.vertices.front()] - m.uv[a];
  const double angle = std::atan2(base.x() * ray.y() - base.y() * ray.x(), base.dot(ray));
  EXPECT_NEAR(angle, M_PI / 2, M_PI / 6 + 1e-9);
}

TEST(QuadSideEdge, SmallAngleTakesTheAdjacentFrontEdge) {
  // A corner of the rectangle: α = π/2 < 3π/4.
  Plate p;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(p.fm);
  VertexMetrics metrics(m, *p.cs);
  for (int e = 0; e < m.numElements(); ++e)
    for (int k = 0; k < 3; ++k) {
      if (m.adj[e][k] != kNone || m.uv[m.corners[e][k]] != Vec2(0, 0)) continue;
      const SideEdge side = selectSideEdge(m, metrics, e, k, true, {});
      ASSERT_EQ(side.vertices.size(), 1u);
      EXPECT_TRUE(side.front);
      EXPECT_TRUE(m.boundary[side.vertices.front()]);
      return;
    }
  FAIL() << "no triangle at the corner (0, 0)";
}

TEST(QuadTopEdge, RecoversAnEdgeBySwaps) {
  Plate p;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(p.fm);
  const auto snap = quadtest::snapshot(m);
  // Two inner vertices about three edges apart, not joined.
  int c = kNone, d = kNone, hint = kNone;
  for (int v = 0; v < m.numVertices() && c == kNone; ++v) {
    if (m.boundary[v] || (m.uv[v] - Vec2(1.5, 0.5)).norm() > 0.1) continue;
    c = v;
  }
  ASSERT_NE(c, kNone);
  for (int w = 0; w < m.numVertices(); ++w) {
    const double r = (m.uv[w] - m.uv[c]).norm();
    if (!m.boundary[w] && r > 2.5 * p.h && r < 3.5 * p.h) d = w;
  }
  for (int e = 0; e < m.numElements(); ++e)
    if (m.cornerIndex(e, c) != kNone) hint = e;
  ASSERT_NE(d, kNone);
  ASSERT_FALSE(hasEdge(m, c, d, hint));
  ASSERT_TRUE(recoverTopEdge(m, c, d, hint, 40));
  quadtest::expectValid(m, snap);
  for (int e = 0; e < m.numElements(); ++e)
    if (m.alive(e) && m.cornerIndex(e, c) != kNone) hint = e;
  EXPECT_TRUE(hasEdge(m, c, d, hint));
}

TEST(QuadSeam, ClosesASmallAngle) {
  // Two quads either side of a wedge at a = (0, 0) of about 17°: triangles (a, c, b) and
  // (c, x, b) between them; the seam merges b and c at their midpoint.
  FaceMesh fm;
  fm.uv = {Vec2(0, 0),    Vec2(1, -1.2), Vec2(3, -1.2), Vec2(3.5, 0), Vec2(3, 1.2),
           Vec2(1, 1.2),  Vec2(2, 0.3),  Vec2(2, -0.3)};
  const int a = 0, p1 = 1, p2 = 2, x = 3, p4 = 4, p3 = 5, b = 6, c = 7;
  fm.node = {0, 1, 2, 3, 4, 5, -1, -1};
  fm.triangles = {{a, c, b}, {c, x, b}, {c, p2, x}, {b, x, p4}};
  fm.quads = {{a, p1, p2, c}, {a, b, p4, p3}};
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(fm);
  const auto snap = quadtest::snapshot(m);
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, -1.2, 3.5, 1.2)}), 1.0);
  VertexMetrics metrics(m, *cs);
  const SeamResult r = closeSeam(m, metrics, 0, 0, true, {});
  ASSERT_TRUE(r.done);
  quadtest::expectValid(m, snap);
  EXPECT_EQ(count(m, 4), 2);
  EXPECT_EQ(count(m, 3), 2);
  EXPECT_NEAR((m.uv[r.vertex] - Vec2(2, 0)).norm(), 0, 1e-12);
  m.compact();
  m.dropUnusedVertices();
  EXPECT_EQ(m.numVertices(), 7);
  quadtest::expectValid(m, snap);
}

TEST(QuadSeam, RefusesAWideAngle) {
  Plate p;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(p.fm);
  VertexMetrics metrics(m, *p.cs);
  const auto [e, k] = straightBoundaryEdge(m, metrics);
  ASSERT_NE(e, kNone);
  EXPECT_FALSE(closeSeam(m, metrics, e, k, true, {}).done);
}

/// The seam's wedge at a = (0, 0) with the lower front edge (a, c) three times as long as
/// the upper (a, b): quad (a, p1, p2, c) below, (a, b, p4, p3) above, triangles between.
struct UnequalWedge {
  static constexpr int a = 0, p1 = 1, p2 = 2, x = 3, p4 = 4, p3 = 5, b = 6, c = 7;
  FaceMesh fm;
  std::shared_ptr<CSAnalytic2d> cs;
  explicit UnequalWedge(double cx) {
    fm.uv = {Vec2(0, 0), Vec2(0, -1.3), Vec2(3, -1.3), Vec2(4, 0.5), Vec2(1, 1.2), Vec2(0, 1.2), Vec2(1, 0.25), Vec2(cx, -0.3)};
    fm.node = {0, 1, 2, 3, 4, 5, -1, -1};
    fm.triangles = {{a, c, b}, {c, x, b}, {c, p2, x}, {b, x, p4}};
    fm.quads = {{a, p1, p2, c}, {a, b, p4, p3}};
    cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, -1.3, 4, 1.2)}), 1.0);
  }
};

TEST(QuadTransitionSeam, SplitsTheLongerEdgeOfAnUnequalWedge) {
  UnequalWedge w(3.0);  // |ac| / |ab| = 2.9, angle about 20°
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(w.fm);
  const auto snap = quadtest::snapshot(m);
  VertexMetrics metrics(m, *w.cs);
  const TransitionResult r = transitionSeam(m, metrics, 0, 0, true);
  ASSERT_TRUE(r.done);
  quadtest::expectValid(m, snap);
  EXPECT_EQ(count(m, 4), 3);
  EXPECT_EQ(count(m, 3), 4);  // the region keeps its triangles
  EXPECT_NEAR((m.uv[r.vertex] - Vec2(1.5, -0.15)).norm(), 0, 1e-12);
  // The new quad has a, the reshaped one m instead of a; the front runs c → m → b.
  EXPECT_NE(m.cornerIndex(r.quad, UnequalWedge::a), kNone);
  EXPECT_NE(m.cornerIndex(r.quad, r.vertex), kNone);
  EXPECT_EQ(m.cornerIndex(r.reshaped, UnequalWedge::a), kNone);
  EXPECT_GE(elementQuality(m, metrics, m.corners[r.quad]), 0.3);
  EXPECT_FALSE(m.alive(r.from));
  int front = 0;  // triangle edges against a quad at m
  for (int e = 0; e < m.numElements(); ++e)
    if (m.isTriangle(e) && m.cornerIndex(e, r.vertex) != kNone)
      for (int k = 0; k < 3; ++k) front += m.adj[e][k] != kNone && m.isQuad(m.adj[e][k]);
  EXPECT_EQ(front, 2);
}

TEST(QuadTransitionSeam, LeavesEqualEdgesToTheSeam) {
  UnequalWedge w(1.2);  // |ac| / |ab| = 1.2
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(w.fm);
  VertexMetrics metrics(m, *w.cs);
  const auto corners = m.corners;
  EXPECT_FALSE(transitionSeam(m, metrics, 0, 0, true).done);
  EXPECT_EQ(m.corners, corners);
  EXPECT_EQ(m.numVertices(), 8);
  EXPECT_TRUE(closeSeam(m, metrics, 0, 0, true).done);
}

/// A straight front y = 0 over two quads, the edge (v, L) three times as long as (s, v); v
/// and t inside, the region above: triangles (v, L, t), (v, t, s) at v.
struct UnequalFront {
  static constexpr int s2 = 0, q = 1, p = 2, L = 3, w2 = 4, w1 = 5, s = 6, v = 7, t = 8;
  FaceMesh fm;
  std::shared_ptr<CSAnalytic2d> cs;
  UnequalFront() {
    fm.uv = {Vec2(-0.8, -1.6), Vec2(0, -1.6), Vec2(2.4, -1.6), Vec2(2.4, 0), Vec2(2.4, 1.6),
             Vec2(-0.8, 1.6), Vec2(-0.8, 0), Vec2(0, 0), Vec2(0.9, 1.0)};
    fm.node = {0, 1, 2, 3, 4, 5, 6, -1, -1};
    fm.triangles = {{v, L, t}, {v, t, s}, {L, w2, t}, {t, w2, w1}, {s, t, w1}};
    fm.quads = {{v, q, p, L}, {s, s2, q, v}};
    cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(-0.8, -1.6, 2.4, 1.6)}), 1.0);
  }
};

TEST(QuadTransitionSplit, GivesTheFrontANodeOnTheLongEdge) {
  UnequalFront f;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(f.fm);
  const auto snap = quadtest::snapshot(m);
  VertexMetrics metrics(m, *f.cs);
  const TransitionResult r = transitionSplit(m, metrics, 0, 0, true, M_PI / 6);
  ASSERT_TRUE(r.done);
  quadtest::expectValid(m, snap);
  EXPECT_EQ(count(m, 4), 4);
  EXPECT_EQ(count(m, 3), 5);
  EXPECT_NEAR((m.uv[r.vertex] - Vec2(1.2, 0)).norm(), 0, 1e-12);
  EXPECT_LT(m.uv[UnequalFront::v].y(), 0);  // v left the front for the quad side
  for (int e : {r.quad, r.reshaped, r.extra}) {
    ASSERT_TRUE(m.isQuad(e));
    EXPECT_GE(elementQuality(m, metrics, m.corners[e]), 0.3);
  }
  // The front runs L → m → s: no region triangle has v any more.
  for (int e = 0; e < m.numElements(); ++e)
    if (m.isTriangle(e)) EXPECT_EQ(m.cornerIndex(e, UnequalFront::v), kNone);
}

TEST(QuadTransitionSplit, RefusesAModestRatioAndTheBoundary) {
  UnequalFront f;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(f.fm);
  VertexMetrics metrics(m, *f.cs);
  const auto corners = m.corners;
  const auto uv = m.uv;
  TransitionSplitOptions o;
  o.splitRatio = 3.5;  // the ratio is 3
  EXPECT_FALSE(transitionSplit(m, metrics, 0, 0, true, M_PI / 6, o).done);
  // From the triangle (v, L, t) at L: L is on the face boundary and may not move.
  EXPECT_FALSE(transitionSplit(m, metrics, 0, 0, false, M_PI / 6).done);
  EXPECT_EQ(m.corners, corners);
  EXPECT_EQ(m.uv, uv);
}

/// A whole conversion with `method`: valid, boundary kept, quads formed by morphing (with
/// transition seams and splits), an even number of triangles left, the same result twice.
void checkConversion(QuadMethod method) {
  Plate p;
  MergeOptions o;
  o.method = method;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(p.fm);
  const auto snap = quadtest::snapshot(m);
  VertexMetrics metrics(m, *p.cs);
  const MergeStats st = mergeFront(m, metrics, o);
  quadtest::expectValid(m, snap);
  EXPECT_GT(st.morphed, st.quads / 4);
  // The plate's front meets unequal edges (after seams and side-edge splits): the corrections
  // of fig. 4.14 run inside the whole conversion, which stays valid.
  EXPECT_GT(st.transitionSeams, 0);
  EXPECT_GT(st.transitionSplits, 0);
  EXPECT_EQ(st.quads, count(m, 4));
  EXPECT_EQ(count(m, 3) % 2, 0);
  EXPECT_LT(count(m, 3), 0.2 * count(m, 4));
  for (int e = 0; e < m.numElements(); ++e)
    if (m.isQuad(e)) {
      EXPECT_GE(elementQuality(m, metrics, m.corners[e]), o.minQuality);
    }
  QuadMesh2d again = QuadMesh2d::fromFaceMesh(p.fm);
  VertexMetrics metrics2(again, *p.cs);
  mergeFront(again, metrics2, o);
  EXPECT_EQ(again.corners, m.corners);
  EXPECT_EQ(again.uv, m.uv);
  m.compact();
  m.dropUnusedVertices();
  quadtest::expectValid(m, snap);
  std::vector<int> used(m.numVertices(), 0);
  for (int e = 0; e < m.numElements(); ++e)
    for (int k = 0; k < m.sides(e); ++k) used[m.corners[e][k]] = 1;
  for (int v = 0; v < m.numVertices(); ++v) EXPECT_TRUE(used[v] || m.boundary[v]) << v;
}

TEST(QuadMorph, MorphingConversionStaysValid) { checkConversion(QuadMethod::Morph); }
TEST(QuadMorph, MixedConversionStaysValid) { checkConversion(QuadMethod::Mixed); }

TEST(QuadChain, TwoTrianglesAcrossTwoQuadsBecomeThreeQuads) {
  // A strip over 0..4: vertex 2i at (i, 0), 2i + 1 at (i, 1), vertex 9 lowered to (4, 0.5).
  // Triangles (0, 2, 1), (6, 8, 9) at the ends, the chain triangle (1, 2, 3) – quad
  // (2, 4, 5, 3) – quad (4, 6, 7, 5) – triangle (6, 9, 7): an 8-gon, re-quadrangulated
  // into 3 quads.
  FaceMesh fm;
  for (int i = 0; i <= 4; ++i) {
    fm.uv.push_back(Vec2(i, 0));
    fm.uv.push_back(Vec2(i, 1));
  }
  fm.uv[9] = Vec2(4, 0.5);
  for (std::size_t i = 0; i < fm.uv.size(); ++i) fm.node.push_back(static_cast<int>(i));
  fm.triangles = {{0, 2, 1}, {6, 8, 9}, {1, 2, 3}, {6, 9, 7}};
  fm.quads = {{2, 4, 5, 3}, {4, 6, 7, 5}};
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(fm);
  const auto snap = quadtest::snapshot(m);
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, 0, 4, 1)}), 1.0);
  VertexMetrics metrics(m, *cs);
  const std::array<int, 4> chain{2, 4, 5, 3};  // triangles get ids 0–3 in order, then the quads
  ASSERT_TRUE(quadrangulateChain(m, metrics, chain));
  quadtest::expectValid(m, snap);
  EXPECT_EQ(count(m, 4), 3);
  EXPECT_EQ(count(m, 3), 2);
  for (int e = 0; e < m.numElements(); ++e)
    if (m.isQuad(e)) {
      EXPECT_GT(elementQuality(m, metrics, m.corners[e]), 0.44);  // the best worst: sin 26.6° at (3, 1)
    }
}

TEST(QuadChain, RefusesAChainThroughATriangle) {
  Plate p;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(p.fm);
  VertexMetrics metrics(m, *p.cs);
  // Three triangles in a row: the middle one is not a quad.
  const int t = 0, u = m.adj[0][0];
  ASSERT_NE(u, kNone);
  int w = kNone;
  for (int k = 0; k < 3; ++k)
    if (m.adj[u][k] != t && m.adj[u][k] != kNone) w = m.adj[u][k];
  ASSERT_NE(w, kNone);
  const std::array<int, 3> chain{t, u, w};
  EXPECT_FALSE(quadrangulateChain(m, metrics, chain));
}

TEST(QuadPole, PoleTrianglesAreSetAsideAndPutBack) {
  // A strip whose top side is a pole: vertices 3, 4, 5 on one node.
  FaceMesh fm;
  fm.uv = {Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(0, 1), Vec2(1, 1), Vec2(2, 1), Vec2(1, 0.5)};
  fm.node = {0, 1, 2, 3, 3, 3, -1};
  fm.triangles = {{0, 1, 6}, {1, 2, 6}, {2, 5, 6}, {5, 4, 6}, {4, 3, 6}, {3, 0, 6}};
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(fm);
  const std::vector<Corners> poles = detachPoleTriangles(m);
  EXPECT_EQ(poles.size(), 2u);
  EXPECT_EQ(facetest::joined(m.validate()), "");
  EXPECT_EQ(count(m, 3), 4);
  EXPECT_TRUE(m.boundary[6]);
  reattachTriangles(m, poles);
  EXPECT_EQ(count(m, 3), 6);
}

}  // namespace
