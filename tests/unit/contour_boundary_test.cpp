// faceBoundary on small analytic models: closed loops in (u, v), the face on the left (outer
// counter-clockwise, holes clockwise, reversed faces normalised), shared nodes, seams (one
// node at u and u + 2π), periodic shifts of pcurves, poles (repeated nodes), pcurves not
// parameterized like their 3D curve, open loops rejected naming the face.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contour_test_models.h"
#include "mesher/core/Error.h"
#include "mesher/surface/ContourDiscretization.h"

using namespace aniso;
using namespace aniso::test;

namespace {

/// The segment x = t², y = z = 0 for t ∈ [0, 1]: the bottom edge of the unit square,
/// parameterized unlike its pcurve (x = t), as in CAD files where SameParameter fails.
class SquaredLine final : public ParametricCurve3d {
 public:
  Vec3 point(double t) const override { return {t * t, 0, 0}; }
  Curve3dD2 d2(double t) const override { return {point(t), Vec3(2 * t, 0, 0), Vec3(2, 0, 0)}; }
  double tMin() const override { return 0; }
  double tMax() const override { return 1; }
  std::unique_ptr<ParametricCurve3d> clone() const override { return std::make_unique<SquaredLine>(); }
};

struct Boundaries {
  std::vector<std::unique_ptr<CSAnalytic2d>> spaces;
  SurfaceMesh mesh;
  std::vector<EdgeDiscretization> edges;

  Boundaries(const Model& m, double h, double gMin = 0) {
    std::vector<const ControlSpace2d*> ptrs;
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      spaces.push_back(space(m, static_cast<int>(f), isotropic(h), gMin));
      ptrs.push_back(spaces.back().get());
    }
    edges = discretizeEdges(m, ptrs, {}, mesh);
  }
};

/// Each boundary node's (u, v) maps onto its global node in 3D, and consecutive nodes are
/// less than half a period apart (no jump across a seam).
void expectConsistent(const Model& m, const FaceBoundary& b, const SurfaceMesh& mesh, double maxStep) {
  const ParametricSurface& s = *m.faces[b.face].surface;
  for (const auto& loop : b.loops) {
    ASSERT_GE(loop.size(), 3u);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      EXPECT_NEAR((s.point(loop[i].uv) - mesh.nodes[loop[i].node]).norm(), 0, 1e-9) << "node " << i;
      EXPECT_LT((loop[(i + 1) % loop.size()].uv - loop[i].uv).norm(), maxStep) << "step " << i;
    }
  }
}

}  // namespace

TEST(ContourBoundary, SquareIsCounterClockwiseAndClosed) {
  const Model m = unitSquare();
  const Boundaries r(m, 0.1);
  const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
  EXPECT_EQ(b.face, 0);
  ASSERT_EQ(b.loops.size(), 1u);
  ASSERT_EQ(b.loops[0].size(), 40u);  // 4 × 10 segments, every node once
  EXPECT_NEAR(signedArea(b.loops[0]), 1.0, 1e-12);
  EXPECT_EQ(b.loops[0][0].node, 0);   // starts at the first use's start vertex
  EXPECT_EQ(b.loops[0][10].node, 1);
  expectConsistent(m, b, r.mesh, 0.11);
}

TEST(ContourBoundary, ReversedFaceIsNormalised) {
  // Model loops of a reversed face have the face on the right (clockwise outer loop).
  const Model m = unitSquare(true);
  const Boundaries r(m, 0.25);
  const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
  EXPECT_NEAR(signedArea(b.loops[0]), 1.0, 1e-12);
  expectConsistent(m, b, r.mesh, 0.26);
}

TEST(ContourBoundary, HoleIsClockwise) {
  ModelBuilder bld;
  const int f = bld.face(xyPlane(), box(0, 0, 1, 1));
  polygonLoop(bld, f, {bld.vertex({0, 0, 0}), bld.vertex({1, 0, 0}), bld.vertex({1, 1, 0}), bld.vertex({0, 1, 0})}, true);
  polygonLoop(bld, f, {bld.vertex({0.4, 0.4, 0}), bld.vertex({0.4, 0.6, 0}), bld.vertex({0.6, 0.6, 0}), bld.vertex({0.6, 0.4, 0})},
              false);
  const Model& m = bld.m;
  const Boundaries r(m, 0.05);
  const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
  ASSERT_EQ(b.loops.size(), 2u);
  EXPECT_NEAR(signedArea(b.loops[0]), 1.0, 1e-12);
  EXPECT_NEAR(signedArea(b.loops[1]), -0.04, 1e-12);
  EXPECT_EQ(b.loops[1].size(), 16u);
  expectConsistent(m, b, r.mesh, 0.06);
}

TEST(ContourBoundary, SharedEdgeRunsOppositeWays) {
  const Model m = twoSquares();
  const Boundaries r(m, 0.2);
  const FaceBoundary b0 = faceBoundary(m, 0, r.edges, r.mesh), b1 = faceBoundary(m, 1, r.edges, r.mesh);
  EXPECT_NEAR(signedArea(b0.loops[0]), 1.0, 1e-12);
  EXPECT_NEAR(signedArea(b1.loops[0]), 1.0, 1e-12);
  // Directed boundary segments: each shared one appears once in each direction.
  std::vector<std::pair<int, int>> s0, s1;
  for (std::size_t i = 0; i < b0.loops[0].size(); ++i)
    s0.push_back({b0.loops[0][i].node, b0.loops[0][(i + 1) % b0.loops[0].size()].node});
  for (std::size_t i = 0; i < b1.loops[0].size(); ++i)
    s1.push_back({b1.loops[0][(i + 1) % b1.loops[0].size()].node, b1.loops[0][i].node});
  int common = 0;
  for (const auto& s : s0) common += static_cast<int>(std::count(s1.begin(), s1.end(), s));
  EXPECT_EQ(common, 5);  // the shared edge's 5 segments
}

TEST(ContourBoundary, SeamGivesOneNodeAtTwoParameters) {
  const Model m = cylinder(1, 2);
  const Boundaries r(m, 0.25);
  const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
  ASSERT_EQ(b.loops.size(), 1u);
  const auto& loop = b.loops[0];
  EXPECT_NEAR(signedArea(loop), 2 * kPi * 2, 1e-9);
  expectConsistent(m, b, r.mesh, kPi);
  // Every seam node (vertices included) appears twice, at u = 0 and u = 2π.
  const EdgeDiscretization& seam = r.edges[2];
  ASSERT_EQ(seam.nodes.size(), 9u);  // 2 / 0.25 = 8 segments
  for (int n : seam.nodes) {
    std::vector<Vec2> at;
    for (const BoundaryNode& bn : loop)
      if (bn.node == n) at.push_back(bn.uv);
    ASSERT_EQ(at.size(), 2u) << "node " << n;
    EXPECT_NEAR(std::abs(at[0].x() - at[1].x()), 2 * kPi, 1e-12);
    EXPECT_NEAR(at[0].y(), at[1].y(), 1e-12);
  }
}

TEST(ContourBoundary, PcurveStoredOnePeriodAwayIsMovedBack) {
  for (double shift : {2 * kPi, -4 * kPi}) {
    const Model m = cylinder(1, 2, shift);
    const Boundaries r(m, 0.25);
    const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
    EXPECT_NEAR(signedArea(b.loops[0]), 4 * kPi, 1e-9) << shift;
    expectConsistent(m, b, r.mesh, kPi);
    for (const BoundaryNode& n : b.loops[0]) {
      EXPECT_GE(n.uv.x(), -1e-12);
      EXPECT_LE(n.uv.x(), 2 * kPi + 1e-12);
    }
  }
}

TEST(ContourBoundary, LoopIsMovedOntoTheFaceBounds) {
  // Every pcurve stored one period to the right of the face's bounds: the loop is chained
  // there, then moved back onto the bounds (where the control space is).
  Model m = cylinder(1, 2, 2 * kPi);
  for (ModelEdge& e : m.edges)
    for (PCurve& pc : e.pcurves)
      if (&e != &m.edges[1]) {
        const auto* line = dynamic_cast<const Line2d*>(pc.curve.get());
        ASSERT_NE(line, nullptr);
        const Vec2 a = line->point(pc.t0), c = line->point(pc.t1);
        pc.curve = std::make_shared<Line2d>(a + Vec2(2 * kPi, 0), c + Vec2(2 * kPi, 0), pc.t0, pc.t1);
      }
  const Boundaries r(m, 0.5);
  const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
  Box2 uv;
  for (const BoundaryNode& n : b.loops[0]) uv.add(n.uv);
  EXPECT_NEAR(uv.lo.x(), 0, 1e-12);
  EXPECT_NEAR(uv.hi.x(), 2 * kPi, 1e-12);
}

TEST(ContourBoundary, PolesRepeatTheVertexNode) {
  const Model m = sphere(1);
  const Boundaries r(m, 0.2, 0.04);
  const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
  const auto& loop = b.loops[0];
  EXPECT_NEAR(signedArea(loop), 2 * kPi * kPi, 1e-9);
  // 6 pole pieces at each pole: 7 consecutive boundary nodes on each pole's vertex node.
  for (int pole : {0, 1}) {
    int count = 0;
    for (const BoundaryNode& n : loop) count += n.node == pole;
    EXPECT_EQ(count, 7) << "pole " << pole;
  }
  int repeats = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) repeats += loop[i].node == loop[(i + 1) % loop.size()].node;
  EXPECT_EQ(repeats, 12);
  expectConsistent(m, b, r.mesh, kPi);
}

TEST(ContourBoundary, OpenLoopIsRejectedNamingTheFace) {
  // A cylinder face bounded by its two circles without a seam: each loop winds around the
  // surface and cannot close in (u, v).
  Model m = cylinder(1, 2);
  ModelFace& f = m.faces[0];
  f.loops = {{{{0, false, 0}}, true}, {{{1, true, 0}}, false}};
  const Boundaries r(m, 0.5);
  try {
    faceBoundary(m, 0, r.edges, r.mesh);
    FAIL() << "the loop does not close";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("face 1 loop 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not closed"), std::string::npos) << e.what();
  }
  // A loop whose uses do not chain (wrong orientation of one use).
  Model bad = unitSquare();
  bad.faces[0].loops[0].uses[2].reversed = true;
  const Boundaries rb(bad, 0.5);
  EXPECT_THROW(faceBoundary(bad, 0, rb.edges, rb.mesh), MeshingError);
}

TEST(ContourBoundary, PcurveParameterizedUnlikeItsEdgeIsProjected) {
  Model m = unitSquare();
  m.edges[0].curve = std::make_shared<SquaredLine>();
  const Boundaries r(m, 0.1);
  const EdgeDiscretization& d = r.edges[0];
  ASSERT_EQ(d.nodes.size(), 11u);  // measured along the pcurve: 10 segments, t = i / 10
  const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
  // The inner nodes sit at x = t² in 3D; their (u, v) follow them, not c_p(t) = (t, 0).
  for (int i = 1; i < 10; ++i) {
    const BoundaryNode& n = b.loops[0][i];
    ASSERT_EQ(n.node, d.nodes[i]);
    EXPECT_NEAR(n.uv.x(), d.t[i] * d.t[i], 1e-9) << i;
    EXPECT_NEAR(n.uv.y(), 0, 1e-12);
  }
  expectConsistent(m, b, r.mesh, 0.2);
}

namespace {

/// The unit square with a triangular hole touching the outer loop at the vertex (0.5, 0)
/// (`touch`, tolerance `vertexTol`); the hole's pcurves end at (0.5 + offset, 0).
Model holeTouchingTheOuterLoop(double offset, double vertexTol, int& touch) {
  ModelBuilder bld;
  const int f = bld.face(xyPlane(), box(0, 0, 1, 1));
  touch = bld.vertex({0.5, 0, 0});
  bld.m.vertices[touch].tolerance = vertexTol;
  polygonLoop(bld, f, {bld.vertex({0, 0, 0}), touch, bld.vertex({1, 0, 0}), bld.vertex({1, 1, 0}), bld.vertex({0, 1, 0})},
              true);
  const int a = bld.vertex({0.4, 0.3, 0}), c = bld.vertex({0.6, 0.3, 0});
  const Vec2 off(0.5 + offset, 0);
  const int e0 = bld.line(touch, a), e1 = bld.line(a, c), e2 = bld.line(c, touch);
  const int k0 = bld.pcurve(e0, f, std::make_shared<Line2d>(off, Vec2(0.4, 0.3)));
  const int k1 = bld.pcurve(e1, f, std::make_shared<Line2d>(Vec2(0.4, 0.3), Vec2(0.6, 0.3)));
  const int k2 = bld.pcurve(e2, f, std::make_shared<Line2d>(Vec2(0.6, 0.3), off));
  bld.loop(f, {{e0, false, k0}, {e1, false, k1}, {e2, false, k2}}, false);
  return bld.m;
}

/// The (u, v) of every copy of `node` in the face's loops.
std::vector<Vec2> copiesOf(const FaceBoundary& b, int node) {
  std::vector<Vec2> at;
  for (const auto& loop : b.loops)
    for (const BoundaryNode& n : loop)
      if (n.node == node) at.push_back(n.uv);
  return at;
}

}  // namespace

TEST(ContourBoundary, NodeTouchingTwoLoopsHasOneParameterPoint) {
  // The hole's pcurves end 1e-13 away from the vertex (round-off of two different pcurves).
  int touch = -1;
  const Model m = holeTouchingTheOuterLoop(1e-13, 0, touch);
  const Boundaries r(m, 0.1);
  const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
  ASSERT_EQ(b.loops.size(), 2u);
  const std::vector<Vec2> at = copiesOf(b, touch);
  ASSERT_EQ(at.size(), 2u);
  EXPECT_EQ(at[0], at[1]);
  EXPECT_LT(signedArea(b.loops[1]), 0);
}

TEST(ContourBoundary, CopiesOfAVertexWithinItsToleranceHaveOneParameterPoint) {
  // The hole's pcurves end 1e-7 from the vertex (an edge a fuse embedded in a face, whose
  // pcurve ends within the vertex's tolerance but far beyond round-off: OCCT's sample
  // bearing, balls imprinted on their rings): one (u, v) when the vertex's tolerance (1e-6)
  // covers the offset, two when it does not (1e-8).
  for (const double tol : {1e-6, 1e-8}) {
    int touch = -1;
    const Model m = holeTouchingTheOuterLoop(1e-7, tol, touch);
    const Boundaries r(m, 0.1);
    const std::vector<Vec2> at = copiesOf(faceBoundary(m, 0, r.edges, r.mesh), touch);
    ASSERT_EQ(at.size(), 2u);
    if (tol > 1e-7) EXPECT_EQ(at[0], at[1]);
    else EXPECT_NEAR((at[0] - at[1]).norm(), 1e-7, 1e-12);
  }
}

TEST(ContourBoundary, ShortEdgeDroppedUnderAVertexToleranceIsBridgedAsAPole) {
  // The unit square with its corner (1, 1) cut by a short edge that the CAD system dropped,
  // widening the tolerance of the vertex that replaces it (as KiCad's Schurter fuse holder,
  // whose fillet lost its end arc under a 0.17 mm vertex): the edges from (1, 0) and to
  // (0, 1) end at (1, 0.7) and start at (0.7, 1), 30 % of the extent apart in (u, v), both
  // within the tolerance of the vertex at (0.85, 0.85). The bridge is the vertex's node
  // repeated along the cut, a pole of the face's boundary.
  ModelBuilder b;
  const int f = b.face(xyPlane(), box(0, 0, 1, 1));
  const int v0 = b.vertex({0, 0, 0}), v1 = b.vertex({1, 0, 0}), vc = b.vertex({0.85, 0.85, 0}), v3 = b.vertex({0, 1, 0});
  b.m.vertices[vc].tolerance = 0.25;
  const auto line = [&](int va, int vb, Vec2 p, Vec2 q) {
    const int e = b.edge(va, vb, std::make_shared<Line3d>(Vec3(p.x(), p.y(), 0), Vec3(q.x(), q.y(), 0)), 0, 1);
    return EdgeUse{e, false, b.pcurve(e, f, std::make_shared<Line2d>(p, q))};
  };
  b.loop(f,
         {line(v0, v1, {0, 0}, {1, 0}), line(v1, vc, {1, 0}, {1, 0.7}), line(vc, v3, {0.7, 1}, {0, 1}),
          line(v3, v0, {0, 1}, {0, 0})},
         true);
  const Boundaries r(b.m, 0.1);
  const FaceBoundary fb = faceBoundary(b.m, 0, r.edges, r.mesh);
  const auto& loop = fb.loops[0];
  EXPECT_NEAR(signedArea(loop), 1 - 0.3 * 0.3 / 2, 1e-9);  // the corner cut, nothing more
  int copies = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    copies += loop[i].node == vc;
    // the copies inside the bridge carry the vertex's own position (FaceBoundary.h)
    if (loop[i].at.allFinite()) EXPECT_EQ(loop[i].at, b.m.vertices[vc].p) << "node " << i;
    EXPECT_LT((loop[(i + 1) % loop.size()].uv - loop[i].uv).norm(), 0.2) << "step " << i;
  }
  EXPECT_GE(copies, 4);  // the cut (0.42 long) at the spacing of its neighbours (0.1)
  EXPECT_GE(std::count_if(loop.begin(), loop.end(), [](const BoundaryNode& n) { return n.at.allFinite(); }), copies - 1);
  // With the vertex's own tolerance the cut is a gap: refused, naming the face.
  b.m.vertices[vc].tolerance = 1e-7;
  const Boundaries tight(b.m, 0.1);
  try {
    faceBoundary(b.m, 0, tight.edges, tight.mesh);
    FAIL() << "the cut is a gap";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("face 1 loop 1: edges 2 and 3 do not meet"), std::string::npos) << e.what();
  }
}
