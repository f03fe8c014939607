// discretizeEdges (thesis sec. 4.3, alg. 4.1) on small analytic models: segment counts from
// the metric length, equal spacing in the metric, the finer of two faces wins, anisotropy,
// even counts, closed edges, parallel edges, poles, node numbering and determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "contour_test_models.h"
#include "mesher/core/Error.h"
#include "mesher/surface/ContourDiscretization.h"
#include "mesher/surface/contour/CornerParity.h"

using namespace aniso;
using namespace aniso::test;

namespace {

/// Discretizes with one control space per face (all faces meshed).
struct Discretized {
  std::vector<std::unique_ptr<CSAnalytic2d>> spaces;
  SurfaceMesh mesh;
  std::vector<EdgeDiscretization> edges;

  Discretized(const Model& m, const std::vector<CSAnalytic2d::MetricFunction>& sizing, const ContourOptions& o = {},
      double gMin = 0) {
    std::vector<const ControlSpace2d*> ptrs;
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
      spaces.push_back(space(m, static_cast<int>(f), sizing[std::min(f, sizing.size() - 1)], gMin));
      ptrs.push_back(spaces.back().get());
    }
    edges = discretizeEdges(m, ptrs, o, mesh);
  }
};

int segments(const EdgeDiscretization& d) { return static_cast<int>(d.nodes.size()) - 1; }

}  // namespace

TEST(ContourDiscretization, UnitEdgeInSizeTenthGetsTenEqualSegments) {
  const Model m = unitSquare();
  const Discretized r(m, {isotropic(0.1)});
  ASSERT_EQ(r.edges.size(), 4u);
  for (int e = 0; e < 4; ++e) {
    const EdgeDiscretization& d = r.edges[e];
    ASSERT_EQ(segments(d), 10) << "edge " << e;
    ASSERT_EQ(d.t.size(), d.nodes.size());
    for (int i = 0; i <= 10; ++i) EXPECT_NEAR(d.t[i], 0.1 * i, 1e-12);
    for (int i = 0; i < 10; ++i)
      EXPECT_NEAR((r.mesh.nodes[d.nodes[i + 1]] - r.mesh.nodes[d.nodes[i]]).norm(), 0.1, 1e-12);
    EXPECT_EQ(d.nodes.front(), m.edges[e].v0);  // vertex nodes first, in vertex order
    EXPECT_EQ(d.nodes.back(), m.edges[e].v1);
  }
  // 4 vertex nodes, then 9 inner nodes per edge in edge order.
  ASSERT_EQ(r.mesh.nodes.size(), 4u + 4 * 9);
  for (int v = 0; v < 4; ++v) {
    EXPECT_EQ(r.mesh.nodeOn[v].kind, NodeOn::Kind::Vertex);
    EXPECT_EQ(r.mesh.nodeOn[v].entity, v);
    EXPECT_EQ(r.mesh.nodes[v], m.vertices[v].p);
  }
  for (int e = 0; e < 4; ++e)
    for (int i = 1; i < 10; ++i) {
      const int n = r.edges[e].nodes[i];
      EXPECT_EQ(n, 4 + 9 * e + (i - 1));
      EXPECT_EQ(r.mesh.nodeOn[n].kind, NodeOn::Kind::Edge);
      EXPECT_EQ(r.mesh.nodeOn[n].entity, e);
      EXPECT_DOUBLE_EQ(r.mesh.nodeOn[n].t, r.edges[e].t[i]);
    }
  EXPECT_TRUE(r.mesh.triangles.empty());
}

TEST(ContourDiscretization, RoundsTheMetricLength) {
  const Model m = unitSquare();
  EXPECT_EQ(segments(Discretized(m, {isotropic(1 / 3.4)}).edges[0]), 3);
  EXPECT_EQ(segments(Discretized(m, {isotropic(1 / 3.6)}).edges[0]), 4);
  EXPECT_EQ(segments(Discretized(m, {isotropic(50)}).edges[0]), 1);  // never fewer than one
}

TEST(ContourDiscretization, VariableSizeGivesEqualMetricSpacing) {
  // h = 0.05 + 0.2 u along the bottom edge: ∫ du / h = ln(0.25 / 0.05) / 0.2 = 8.047.
  const Model m = unitSquare();
  const Discretized r(m, {[](const Vec2& uv) { return Metric2d::isotropic(0.05 + 0.2 * uv.x()); }});
  const EdgeDiscretization& d = r.edges[0];
  ASSERT_EQ(segments(d), 8);
  const double L = std::log(5.0) / 0.2;
  for (int i = 0; i <= 8; ++i) {
    // s(t) = ln((0.05 + 0.2 t) / 0.05) / 0.2 = i L / 8.
    const double expected = (0.05 * std::exp(0.2 * i * L / 8) - 0.05) / 0.2;
    EXPECT_NEAR(d.t[i], expected, 2e-3) << i;
  }
}

TEST(ContourDiscretization, FinerFaceWinsAndNodesAreShared) {
  const Model m = twoSquares();
  const Discretized r(m, {isotropic(0.1), isotropic(0.25)});
  EXPECT_EQ(segments(r.edges[1]), 10);  // shared edge: the finer face
  EXPECT_EQ(segments(r.edges[0]), 10);
  EXPECT_EQ(segments(r.edges[4]), 4);   // face 1 only
  EXPECT_EQ(segments(r.edges[5]), 4);
  // The shared edge's nodes appear in both faces' boundaries.
  const FaceBoundary b0 = faceBoundary(m, 0, r.edges, r.mesh), b1 = faceBoundary(m, 1, r.edges, r.mesh);
  for (int n : r.edges[1].nodes) {
    int in0 = 0, in1 = 0;
    for (const BoundaryNode& bn : b0.loops[0]) in0 += bn.node == n;
    for (const BoundaryNode& bn : b1.loops[0]) in1 += bn.node == n;
    EXPECT_EQ(in0, 1);
    EXPECT_EQ(in1, 1);
  }
}

TEST(ContourDiscretization, PointwiseMaximumOverFaces) {
  // Face 0 is fine below v = 0.5, face 1 above: each alone would give 10·0.5 + 2·0.5 = 6
  // segments on the shared edge, the pointwise maximum 10 (and equal spacing).
  const Model m = twoSquares();
  const Discretized r(m, {[](const Vec2& uv) { return Metric2d::isotropic(uv.y() < 0.5 ? 0.1 : 0.5); },
                  [](const Vec2& uv) { return Metric2d::isotropic(uv.y() < 0.5 ? 0.5 : 0.1); }});
  const EdgeDiscretization& d = r.edges[1];
  ASSERT_EQ(segments(d), 10);
  for (int i = 0; i <= 10; ++i) EXPECT_NEAR(d.t[i], 0.1 * i, 2e-3);
  EXPECT_EQ(segments(r.edges[0]), 10);  // bottom of face 0: h = 0.1
  EXPECT_EQ(segments(r.edges[2]), 2);   // top of face 0: h = 0.5
}

TEST(ContourDiscretization, AnisotropicMetric) {
  const Model m = unitSquare();
  // h1 = 0.1 along u, h2 = 0.5 along v.
  const Discretized r(m, {[](const Vec2&) { return Metric2d::fromAngle(0, 0.1, 0.5); }});
  EXPECT_EQ(segments(r.edges[0]), 10);
  EXPECT_EQ(segments(r.edges[1]), 2);
  EXPECT_EQ(segments(r.edges[2]), 10);
  EXPECT_EQ(segments(r.edges[3]), 2);
  // Rotated by 45°: |M e_u| = √(½/0.01 + ½/0.25) = √52 ≈ 7.2 on every side.
  const Discretized rot(m, {[](const Vec2&) { return Metric2d::fromAngle(std::numbers::pi / 4, 0.1, 0.5); }});
  for (int e = 0; e < 4; ++e) EXPECT_EQ(segments(rot.edges[e]), 7) << e;
}

TEST(ContourDiscretization, ParameterizationTensorScalesTheLength) {
  // The plane parameterized by u·(2,0,0): an edge of unit parameter length is 2 long.
  ModelBuilder b;
  const int f = b.face(std::make_shared<PlaneSurface>(Vec3::Zero(), Vec3(2, 0, 0), Vec3::UnitY(), 0, 1, 0, 1),
                       box(0, 0, 1, 1));
  const int v0 = b.vertex({0, 0, 0}), v1 = b.vertex({2, 0, 0}), v2 = b.vertex({2, 1, 0}), v3 = b.vertex({0, 1, 0});
  const Vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const int vs[4] = {v0, v1, v2, v3};
  std::vector<EdgeUse> uses;
  for (int i = 0; i < 4; ++i) {
    const int e = b.line(vs[i], vs[(i + 1) % 4]);
    uses.push_back({e, false, b.pcurve(e, f, std::make_shared<Line2d>(uv[i], uv[(i + 1) % 4]))});
  }
  b.loop(f, uses, true);
  const Discretized r(b.m, {isotropic(0.1)});
  EXPECT_EQ(segments(r.edges[0]), 20);
  EXPECT_EQ(segments(r.edges[1]), 10);
}

TEST(ContourDiscretization, EvenSegmentsOnRequest) {
  const Model m = unitSquare();
  ContourOptions o;
  o.evenSegments = true;
  const Discretized r(m, {isotropic(1 / 3.2)}, o);
  for (int e = 0; e < 4; ++e) EXPECT_EQ(segments(r.edges[e]), 4);
  const Discretized one(m, {isotropic(10)}, o);
  for (int e = 0; e < 4; ++e) EXPECT_EQ(segments(one.edges[e]), 2);
}

TEST(ContourDiscretization, ClosedCircleEdge) {
  const Model m = disc(1);
  const Discretized r(m, {isotropic(0.1)});
  const EdgeDiscretization& d = r.edges[0];
  ASSERT_EQ(segments(d), 63);  // round(2π / 0.1)
  EXPECT_EQ(d.nodes.front(), d.nodes.back());
  for (int i = 0; i < 63; ++i) {
    EXPECT_NEAR(d.t[i + 1] - d.t[i], 2 * kPi / 63, 1e-9);
    EXPECT_NEAR(r.mesh.nodes[d.nodes[i]].norm(), 1.0, 1e-12);
  }
  // A coarse size still gives the minimum of a closed edge, and the option raises it.
  EXPECT_EQ(segments(Discretized(m, {isotropic(100)}).edges[0]), 3);
  ContourOptions o;
  o.minSegmentsClosedEdge = 8;
  EXPECT_EQ(segments(Discretized(m, {isotropic(100)}, o).edges[0]), 8);
  o.minSegmentsClosedEdge = 1;  // below 3 a closed edge would collapse
  EXPECT_EQ(segments(Discretized(m, {isotropic(100)}, o).edges[0]), 3);
}

TEST(ContourDiscretization, ParallelEdgesDoNotBothStaySingle) {
  // The arc and the diameter join the same two vertices: with one segment each they would
  // give the same node pair twice (and a two-node loop). The longer one (the arc) is split.
  const Model m = lens();
  const Discretized r(m, {isotropic(100)});
  EXPECT_EQ(segments(r.edges[0]), 2);
  EXPECT_EQ(segments(r.edges[1]), 1);
  const FaceBoundary b = faceBoundary(m, 0, r.edges, r.mesh);
  EXPECT_EQ(b.loops[0].size(), 3u);
  EXPECT_GT(signedArea(b.loops[0]), 0);
}

TEST(ContourDiscretization, PolesAreSplitInTheParametricPlaneOnly) {
  const Model m = sphere(1);
  // A pole is measured one mesh size (0.2 in v) into the face: the ring at colatitude 0.2
  // is 2π sin 0.2 long, 6.2 sizes of 0.2: 6 pieces, all on the vertex node.
  const Discretized r(m, {isotropic(0.2)}, {}, 1e-8);
  for (int e : {1, 2}) {
    const EdgeDiscretization& d = r.edges[e];
    ASSERT_EQ(segments(d), 6) << e;
    for (int n : d.nodes) EXPECT_EQ(n, m.edges[e].v0);
    EXPECT_DOUBLE_EQ(d.t.front(), 0);
    EXPECT_DOUBLE_EQ(d.t.back(), 2 * kPi);
  }
  // The seam (a half meridian, length π) in 0.2: 16 segments, nodes on the meridian.
  const EdgeDiscretization& seam = r.edges[0];
  EXPECT_EQ(segments(seam), 16);
  for (int n : seam.nodes) EXPECT_NEAR(r.mesh.nodes[n].norm(), 1.0, 1e-12);
  EXPECT_EQ(r.mesh.nodes.size(), 2u + 15);  // no node for the pole pieces
  // About 2π pieces whatever the size (2π sin(h)/h), and never fewer than the g_min guard
  // asks for at the pole itself (√g_min = 2 per unit of u in a size of 0.2: 63 pieces).
  EXPECT_EQ(segments(Discretized(m, {isotropic(0.01)}, {}, 1e-8).edges[1]), 6);
  EXPECT_EQ(segments(Discretized(m, {isotropic(0.2)}, {}, 0.16).edges[1]), 13);
}

TEST(ContourDiscretization, OnlyEdgesOfMeshedFaces) {
  const Model m = twoSquares();
  const auto cs = space(m, 1, isotropic(0.25));
  SurfaceMesh mesh;
  const std::vector<EdgeDiscretization> d = discretizeEdges(m, {nullptr, cs.get()}, {}, mesh);
  for (int e : {0, 2, 3}) EXPECT_TRUE(d[e].nodes.empty()) << e;
  for (int e : {1, 4, 5, 6}) EXPECT_EQ(segments(d[e]), 4) << e;
  // Vertices (0,0) and (0,1) are not used by face 1: no nodes.
  EXPECT_EQ(mesh.nodes.size(), 4u + 4 * 3);
  for (std::size_t n = 0; n < 4; ++n) EXPECT_EQ(mesh.nodeOn[n].kind, NodeOn::Kind::Vertex);
  EXPECT_EQ(mesh.nodeOn[0].entity, 1);
  EXPECT_THROW(faceBoundary(m, 0, d, mesh), MeshingError);
}

TEST(ContourDiscretization, Deterministic) {
  const Model m = sphere(1.5);
  const auto sizing = [](const Vec2& uv) { return Metric2d::fromAngle(uv.x(), 0.1 + 0.05 * std::sin(uv.y()), 0.3); };
  const Discretized a(m, {sizing}, {}, 1e-4), b(m, {sizing}, {}, 1e-4);
  ASSERT_EQ(a.mesh.nodes.size(), b.mesh.nodes.size());
  for (std::size_t i = 0; i < a.mesh.nodes.size(); ++i) EXPECT_EQ(a.mesh.nodes[i], b.mesh.nodes[i]);
  for (std::size_t e = 0; e < a.edges.size(); ++e) {
    EXPECT_EQ(a.edges[e].t, b.edges[e].t);
    EXPECT_EQ(a.edges[e].nodes, b.edges[e].nodes);
  }
}

TEST(ContourDiscretization, ErrorsNameTheEdge) {
  Model m = unitSquare();
  const auto cs = space(m, 0, isotropic(0.1));
  SurfaceMesh mesh;
  EXPECT_THROW(discretizeEdges(m, {}, {}, mesh), MeshingError);  // one space per face
  m.edges[2].pcurves.clear();
  try {
    discretizeEdges(m, {cs.get()}, {}, mesh);
    FAIL() << "no pcurve on the meshed face";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("edge 3"), std::string::npos) << e.what();
  }
  Model bad = unitSquare();
  bad.edges[1].t1 = bad.edges[1].t0;
  try {
    discretizeEdges(bad, {cs.get()}, {}, mesh);
    FAIL() << "empty range";
  } catch (const MeshingError& e) {
    EXPECT_NE(std::string(e.what()).find("edge 2"), std::string::npos) << e.what();
  }
}

namespace {

/// A triangle of the plane z = 0 with a corner of `angleDeg` at the origin: (0,0), (10,0),
/// (10, 10 tan a); with `square`, the rectangle [10, 10 + h] × [0, h] (h = 10 tan a) shares
/// its vertical edge (face 1).
Model sharpTriangle(double angleDeg, bool square = false, bool reversed = false) {
  ModelBuilder b;
  const double h = 10 * std::tan(angleDeg * kPi / 180);
  const int f = b.face(xyPlane(-1, 30, -1, 30), box(0, 0, 10, h), reversed);
  std::vector<int> vs = {b.vertex({0, 0, 0}), b.vertex({10, 0, 0}), b.vertex({10, h, 0})};
  if (reversed) std::reverse(vs.begin(), vs.end());
  const std::vector<int> edges = polygonLoop(b, f, vs, true);
  if (square) {
    const int g = b.face(xyPlane(-1, 30, -1, 30), box(10, 0, 10 + h, h));
    const int v20 = b.vertex({10 + h, 0, 0}), v21 = b.vertex({10 + h, h, 0});
    const int shared = edges[1];  // (10,0) -> (10,h)
    const auto lineOn = [&](int e) {
      const Vec3 p = b.m.vertices[b.m.edges[e].v0].p, q = b.m.vertices[b.m.edges[e].v1].p;
      return b.pcurve(e, g, std::make_shared<Line2d>(Vec2(p.x(), p.y()), Vec2(q.x(), q.y())));
    };
    const int e0 = b.line(vs[1], v20), e1 = b.line(v20, v21), e2 = b.line(v21, vs[2]);
    const int k0 = lineOn(e0), k1 = lineOn(e1), k2 = lineOn(e2), ks = lineOn(shared);
    b.loop(g, {{e0, false, k0}, {e1, false, k1}, {e2, false, k2}, {shared, true, ks}}, true);
  }
  return b.m;
}

int faceSegments(const Model& m, const Discretized& r, int f) {
  int n = 0;
  for (const Loop& loop : m.faces[f].loops)
    for (const EdgeUse& u : loop.uses) n += segments(r.edges[u.edge]);
  return n;
}

}  // namespace

TEST(CornerParity, SharpCornersCountedOnTheFaceSide) {
  EXPECT_EQ(contour::sharpCorners(sharpTriangle(3), 0), 1);
  EXPECT_EQ(contour::sharpCorners(sharpTriangle(3, false, true), 0), 1);  // reversed face, clockwise loop
  EXPECT_EQ(contour::sharpCorners(sharpTriangle(10), 0), 0);
  EXPECT_EQ(contour::sharpCorners(unitSquare(), 0), 0);
  // A reflex corner of nearly 360° is not sharp: the square's loop walked backwards puts
  // the face outside, every corner at 270°.
  EXPECT_EQ(contour::sharpCorners(unitSquare(true), 0), 0);
}

TEST(CornerParity, BoundaryCountParityFollowsTheSharpCorners) {
  ContourOptions o;
  o.evenSegments = true;
  for (const double h : {0.3, 1.0, 3.0}) {
    // One face with one sharp corner: an odd boundary count (a free edge takes the odd count).
    const Model one = sharpTriangle(3);
    const Discretized r1(one, {isotropic(h)}, o);
    EXPECT_EQ(faceSegments(one, r1, 0) % 2, 1) << h;
    const Model blunt = sharpTriangle(10);
    const Discretized rb(blunt, {isotropic(h)}, o);
    EXPECT_EQ(faceSegments(blunt, rb, 0) % 2, 0) << h;
    // With a neighbour that has no sharp corner, the neighbour stays even: the odd count goes
    // on a free edge of the triangle, not on the shared one.
    const Model two = sharpTriangle(3, true);
    const Discretized r2(two, {isotropic(h)}, o);
    EXPECT_EQ(faceSegments(two, r2, 0) % 2, 1) << h;
    EXPECT_EQ(faceSegments(two, r2, 1) % 2, 0) << h;
  }
}
