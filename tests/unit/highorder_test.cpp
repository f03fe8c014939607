// Quadratic elements (mesher/highorder): mid-edge nodes of a meshed capped cylinder and a
// sphere (seam, poles) on the analytic surfaces and curves, positive Jacobians, sharing
// between surface and tetrahedra, and elements that curving would invert left straight.
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "contour_test_models.h"
#include "mesher/core/Error.h"
#include "mesher/geometry/ExpressionSurface.h"
#include "mesher/highorder/Order2.h"
#include "mesher/highorder/QuadraticJacobian.h"
#include "mesher/pipeline/SurfaceMesher.h"
#include "tests/unit/mesh_model_fixture.h"

using namespace aniso;
using namespace aniso::test;

namespace {

Vec3 chordMid(const SurfaceMesh& m, int a, int b) { return 0.5 * (m.nodes[a] + m.nodes[b]); }

double triRatio(const SurfaceMesh& m, std::size_t t) {
  const auto& c = m.triangles[t];
  const auto& k = m.triangleMid[t];
  return tri6JacobianRatio({m.nodes[c[0]], m.nodes[c[1]], m.nodes[c[2]]}, {m.nodes[k[0]], m.nodes[k[1]], m.nodes[k[2]]});
}

/// Every mid node: its NodeOn evaluates to its position; face mids on their face's surface.
void expectOnGeometry(const Model& model, const SurfaceMesh& m, double tol) {
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int mid = m.triangleMid[t][k];
      const NodeOn& on = m.nodeOn[mid];
      const Vec3& p = m.nodes[mid];
      if (on.kind == NodeOn::Kind::Edge) {
        EXPECT_LT((model.edges[on.entity].curve->point(on.t) - p).norm(), tol) << "mid " << mid;
      } else {
        ASSERT_EQ(on.kind, NodeOn::Kind::Face) << "mid " << mid;
        EXPECT_EQ(on.entity, m.triangleFace[t]);
        EXPECT_LT((model.faces[on.entity].surface->point(on.uv) - p).norm(), tol) << "mid " << mid;
      }
    }
}

}  // namespace

TEST(HighOrderJacobian, StraightIsOneFoldedIsNegative) {
  const std::array<Vec3, 4> tc = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  std::array<Vec3, 6> tm;
  for (int k = 0; k < 6; ++k) tm[k] = 0.5 * (tc[VolumeMesh::kTetEdges[k][0]] + tc[VolumeMesh::kTetEdges[k][1]]);
  EXPECT_NEAR(tet10JacobianRatio(tc, tm), 1, 1e-12);
  tm[0] += Vec3(0, 0.9, 0);  // mid of edge (0, 1) pushed past the opposite edge's side
  EXPECT_LT(tet10JacobianRatio(tc, tm), 0);

  const std::array<Vec3, 3> c = {Vec3(0, 0, 5), Vec3(2, 0, 5), Vec3(0, 1, 5)};
  std::array<Vec3, 3> m = {Vec3(1, 0, 5), Vec3(1, 0.5, 5), Vec3(0, 0.5, 5)};
  EXPECT_NEAR(tri6JacobianRatio(c, m), 1, 1e-12);
  m[0].y() = 0.2;  // mild bulge inward: still valid
  EXPECT_GT(tri6JacobianRatio(c, m), 0);
  m[0].y() = 0.9;  // past the opposite corner's height: folded
  EXPECT_LT(tri6JacobianRatio(c, m), 0);

  const std::array<Vec3, 4> q = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(0, 2, 0)};
  std::array<Vec3, 4> qm = {Vec3(1, 0, 0), Vec3(2, 1, 0), Vec3(1, 2, 0), Vec3(0, 1, 0)};
  EXPECT_NEAR(quad8JacobianRatio(q, qm), 1, 1e-12);
  qm[0].y() = 2.5;  // the bottom mid node pushed beyond the centre
  EXPECT_LT(quad8JacobianRatio(q, qm), 0);
}

TEST(HighOrder, CylinderMidNodesOnCurvesAndSurfaces) {
  const double r = 1, h = 2;
  const Model model = cappedCylinder(r, h);
  SurfaceMesh mesh = meshModel(model, 0.4);
  const std::size_t linearNodes = mesh.nodes.size();
  const Order2Stats stats = elevateToOrder2(model, mesh);
  ASSERT_EQ(mesh.triangleMid.size(), mesh.triangles.size());
  EXPECT_EQ(stats.straightened, 0);
  EXPECT_EQ(static_cast<std::size_t>(stats.midNodes), 3 * mesh.triangles.size() / 2);  // closed: one per edge
  EXPECT_EQ(mesh.nodes.size(), linearNodes + stats.midNodes);

  const double tol = 1e-6 * model.diagonal();
  std::map<int, int> edgeMids;  // model edge → mid nodes on it
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    EXPECT_GE(triRatio(mesh, t), kMinJacobianRatio) << "triangle " << t;
    for (int k = 0; k < 3; ++k) {
      const int mid = mesh.triangleMid[t][k];
      const Vec3& p = mesh.nodes[mid];
      const double radius = std::hypot(p.x(), p.y());
      if (mesh.triangleFace[t] == 0) {
        EXPECT_NEAR(radius, r, tol) << "lateral mid " << mid;
      } else {
        EXPECT_NEAR(p.z(), mesh.triangleFace[t] == 1 ? 0 : h, tol) << "cap mid " << mid;
        EXPECT_LE(radius, r + tol);
      }
      if (mesh.nodeOn[mid].kind == NodeOn::Kind::Edge) {
        edgeMids[mesh.nodeOn[mid].entity] += 1;
        if (mesh.nodeOn[mid].entity < 2) {  // the circles
          EXPECT_NEAR(radius, r, tol);
          EXPECT_NEAR(p.z(), mesh.nodeOn[mid].entity == 0 ? 0 : h, tol);
        }
        // On the curve between its edge's ends: not at the chord midpoint of a circle.
        const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
        if (mesh.nodeOn[mid].entity < 2) {
          EXPECT_GT((p - chordMid(mesh, a, b)).norm(), tol);
        }
      }
    }
  }
  expectOnGeometry(model, mesh, tol);
  // Each mid node on a model edge is counted by both its triangles; segments = nodes + 1.
  for (int e = 0; e < 3; ++e) {
    int nodes = 0;
    for (std::size_t i = 0; i < linearNodes; ++i)
      nodes += mesh.nodeOn[i].kind == NodeOn::Kind::Edge && mesh.nodeOn[i].entity == e;
    EXPECT_EQ(edgeMids[e], 2 * (nodes + 1)) << "edge " << e;
  }
}

TEST(HighOrder, SphereSeamAndPoles) {
  const Model model = sphere(1);
  SurfaceMesh mesh = meshModel(model, 0.35);
  const Order2Stats stats = elevateToOrder2(model, mesh);
  EXPECT_EQ(stats.straightened, 0);
  const double tol = 1e-6 * model.diagonal();
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    EXPECT_GE(triRatio(mesh, t), kMinJacobianRatio) << "triangle " << t;
    for (int k = 0; k < 3; ++k) {
      const int mid = mesh.triangleMid[t][k];
      EXPECT_NEAR(mesh.nodes[mid].norm(), 1, tol) << "mid " << mid;
      // Near the chord midpoint (not across the seam or the pole).
      const Vec3 c = chordMid(mesh, mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]);
      EXPECT_LT((mesh.nodes[mid] - c).norm(), 0.5 * (mesh.nodes[mesh.triangles[t][k]] - c).norm() + tol);
    }
  }
  expectOnGeometry(model, mesh, tol);
}

TEST(HighOrder, Deterministic) {
  const Model model = cappedCylinder(1, 2);
  const SurfaceMesh linear = meshModel(model, 0.5);
  SurfaceMesh a = linear, b = linear;
  elevateToOrder2(model, a);
  elevateToOrder2(model, b);
  EXPECT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.triangleMid, b.triangleMid);
  EXPECT_THROW(elevateToOrder2(model, a), MeshingError);  // already quadratic
}

TEST(HighOrder, VolumeSharesSurfaceMidNodes) {
  const Model model = unitSquare();
  VolumeMesh vm;
  SurfaceMesh& s = vm.surface;
  const Vec3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int v = 0; v < 4; ++v) s.addNode(corners[v], NodeOn{NodeOn::Kind::Vertex, v, 0, Vec2(0, 0)});
  const int apex = s.addNode({0.5, 0.5, 1}, NodeOn{NodeOn::Kind::Solid, 0, 0, Vec2(0, 0)});
  s.triangles = {{0, 1, 2}, {0, 2, 3}};
  s.triangleFace = {0, 0};
  vm.tets = {{0, 1, 2, apex}, {0, 2, 3, apex}};
  vm.tetSolid = {0, 0};
  const Order2Stats stats = elevateToOrder2(model, vm);
  EXPECT_EQ(stats.midNodes, 5 + 4);
  EXPECT_EQ(stats.straightened, 0);
  ASSERT_EQ(vm.tetMid.size(), 2u);
  for (std::size_t t = 0; t < 2; ++t)
    for (int k = 0; k < 6; ++k) {
      const int a = vm.tets[t][VolumeMesh::kTetEdges[k][0]], b = vm.tets[t][VolumeMesh::kTetEdges[k][1]];
      const int mid = vm.tetMid[t][k];
      EXPECT_LT((s.nodes[mid] - chordMid(s, a, b)).norm(), 1e-12);  // a flat face: straight
      if (a == apex || b == apex) {
        EXPECT_EQ(s.nodeOn[mid].kind, NodeOn::Kind::Solid);
        continue;
      }
      // A boundary edge: the same node as the triangle's.
      bool found = false;
      for (int k2 = 0; k2 < 3; ++k2) {
        const int c = s.triangles[t][k2], d = s.triangles[t][(k2 + 1) % 3];
        if ((c == a && d == b) || (c == b && d == a)) found = s.triangleMid[t][k2] == mid;
      }
      EXPECT_TRUE(found) << "tet " << t << " edge " << k;
      EXPECT_EQ(s.nodeOn[mid].kind, (a == 0 && b == 2) || (a == 2 && b == 0) ? NodeOn::Kind::Face : NodeOn::Kind::Edge);
    }
}

namespace {

/// One face: the cylinder r = 1 around z; nodes placed by (u, v) as face nodes.
struct CylinderPatch {
  Model model;
  std::shared_ptr<CylinderSurface> surface = std::make_shared<CylinderSurface>(Frame(), 1, -1, 1);
  CylinderPatch() {
    ModelBuilder b;
    b.face(surface, box(0, -1, 2 * kPi, 1));
    b.m.bbox.add(Vec3(-1, -1, -1));
    b.m.bbox.add(Vec3(1, 1, 1));
    model = b.m;
  }
  int node(SurfaceMesh& m, const Vec2& uv) const {
    return m.addNode(surface->point(uv), NodeOn{NodeOn::Kind::Face, 0, 0, uv});
  }
};

}  // namespace

TEST(HighOrder, FoldedTriangleLeftStraight) {
  // A triangle of the unit disc with one edge along a quarter of the boundary circle and its
  // third corner between that edge's chord and the arc: curving the edge folds it.
  const Model disk = disc(1);
  SurfaceMesh m;
  const int a = m.addNode({1, 0, 0}, NodeOn{NodeOn::Kind::Vertex, 0, 0, Vec2(0, 0)});
  int b = -1;
  for (int q = 1; q < 4; ++q) {  // the circle's nodes at t = π/2, π, 3π/2
    const double t = q * kPi / 2;
    const int n = m.addNode({std::cos(t), std::sin(t), 0}, NodeOn{NodeOn::Kind::Edge, 0, t, Vec2(0, 0)});
    if (q == 1) b = n;
  }
  const int c = m.addNode({0.6, 0.6, 0}, NodeOn{NodeOn::Kind::Face, 0, 0, Vec2(0.6, 0.6)});
  m.triangles = {{a, c, b}};
  m.triangleFace = {0};
  // The curved element, were it kept, folds: the arc's midpoint is beyond c.
  const Vec3 arcMid(std::sqrt(0.5), std::sqrt(0.5), 0);
  ASSERT_LT(tri6JacobianRatio({m.nodes[a], m.nodes[c], m.nodes[b]},
                              {chordMid(m, a, c), chordMid(m, c, b), arcMid}), 0);

  const Order2Stats stats = elevateToOrder2(disk, m);
  EXPECT_EQ(stats.midNodes, 3);
  EXPECT_EQ(stats.straightened, 1);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(m.nodes[m.triangleMid[0][k]], chordMid(m, m.triangles[0][k], m.triangles[0][(k + 1) % 3]));
  EXPECT_EQ(m.nodeOn[m.triangleMid[0][2]].kind, NodeOn::Kind::Edge);  // still the circle's, on its chord
  EXPECT_NEAR(triRatio(m, 0), 1, 1e-9);
}

TEST(HighOrder, InvertedTetLeftStraightSurfaceKeepsValid) {
  // A tetrahedron on a cylindrical hole's wall: the arc of its boundary edge (a, b) bulges
  // past its fourth corner d, which sits between the chord and the arc.
  const CylinderPatch cyl;
  VolumeMesh vm;
  SurfaceMesh& s = vm.surface;
  const double theta = 1, sagitta = 1 - std::cos(theta / 2);
  const int a = cyl.node(s, {0, 0}), b = cyl.node(s, {theta, 0}), c = cyl.node(s, {theta / 2, 0.3});
  s.triangles = {{a, b, c}};
  s.triangleFace = {0};
  const Vec3 dir(std::cos(theta / 2), std::sin(theta / 2), 0);
  const int d = s.addNode((std::cos(theta / 2) + sagitta / 2) * dir, NodeOn{NodeOn::Kind::Solid, 0, 0, Vec2(0, 0)});
  std::array<int, 4> tet = {a, b, c, d};
  const auto& x = s.nodes;
  if ((x[b] - x[a]).dot((x[c] - x[a]).cross(x[d] - x[a])) < 0) std::swap(tet[0], tet[1]);
  vm.tets = {tet};
  vm.tetSolid = {0};

  const Order2Stats stats = elevateToOrder2(cyl.model, vm);
  EXPECT_EQ(stats.midNodes, 6);
  EXPECT_EQ(stats.straightened, 1);  // the tetrahedron; the triangle alone was fine
  std::array<Vec3, 4> corner;
  std::array<Vec3, 6> mid;
  for (int i = 0; i < 4; ++i) corner[i] = x[vm.tets[0][i]];
  for (int k = 0; k < 6; ++k) mid[k] = x[vm.tetMid[0][k]];
  EXPECT_GE(tet10JacobianRatio(corner, mid), kMinJacobianRatio);
  for (int k = 0; k < 3; ++k)  // the boundary triangle's mid nodes are the tetrahedron's
    EXPECT_NE(std::find(vm.tetMid[0].begin(), vm.tetMid[0].end(), s.triangleMid[0][k]), vm.tetMid[0].end());
  // The edge (a, b) is back on its chord; the curved position would have inverted the tet.
  int ab = -1;
  for (int k = 0; k < 3; ++k)
    if (s.triangles[0][k] == a && s.triangles[0][(k + 1) % 3] == b) ab = s.triangleMid[0][k];
  ASSERT_GE(ab, 0);
  EXPECT_EQ(x[ab], chordMid(s, a, b));
  std::array<Vec3, 6> curvedMid = mid;
  for (int k = 0; k < 6; ++k)
    if (vm.tetMid[0][k] == ab) curvedMid[k] = cyl.surface->point({theta / 2, 0});
  EXPECT_LT(tet10JacobianRatio(corner, curvedMid), 0);
}

TEST(HighOrder, QuadMidNodesOnSurface) {
  // Two quads of the cylinder sharing an edge: 8-node quads with their mid nodes on r = 1.
  const CylinderPatch cyl;
  SurfaceMesh m;
  int n[2][3];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 3; ++j) n[i][j] = cyl.node(m, {0.4 * j, 0.5 * i});
  m.quads = {{n[0][0], n[0][1], n[1][1], n[1][0]}, {n[0][1], n[0][2], n[1][2], n[1][1]}};
  m.quadFace = {0, 0};
  const Order2Stats stats = elevateToOrder2(cyl.model, m);
  EXPECT_EQ(stats.midNodes, 7);  // 4 + 4 edges, one shared
  EXPECT_EQ(stats.straightened, 0);
  ASSERT_EQ(m.quadMid.size(), 2u);
  EXPECT_EQ(m.quadMid[0][1], m.quadMid[1][3]);  // the shared edge's node
  for (std::size_t q = 0; q < 2; ++q) {
    std::array<Vec3, 4> c, mid;
    for (int k = 0; k < 4; ++k) {
      c[k] = m.nodes[m.quads[q][k]];
      mid[k] = m.nodes[m.quadMid[q][k]];
      EXPECT_NEAR(std::hypot(mid[k].x(), mid[k].y()), 1, 1e-9);
      EXPECT_EQ(m.nodeOn[m.quadMid[q][k]].kind, NodeOn::Kind::Face);
    }
    EXPECT_GE(quad8JacobianRatio(c, mid), kMinJacobianRatio);
  }
}

TEST(HighOrder, SeamOfASurfaceNotDeclaredPeriodic) {
  // A cylinder given by expressions on u in [0, 2π] without periodicity: an edge across
  // the seam has its (u, v) midpoint on the far side; the mid node must still be the near one.
  SurfaceDomain d;
  d.u0 = 0;
  d.u1 = 2 * kPi;
  d.v0 = -1;
  d.v1 = 1;
  ModelBuilder builder;
  builder.face(std::make_shared<ExpressionSurface>("cos(u)", "sin(u)", "v", d), box(0, -1, 2 * kPi, 1));
  builder.m.bbox.add(Vec3(-1, -1, -1));
  builder.m.bbox.add(Vec3(1, 1, 1));
  const Model& model = builder.m;
  SurfaceMesh m;
  auto node = [&](double u, double v) {
    return m.addNode(model.faces[0].surface->point({u, v}), NodeOn{NodeOn::Kind::Face, 0, 0, Vec2(u, v)});
  };
  const int a = node(2 * kPi - 0.2, 0), b = node(0.2, 0), c = node(0, 0.3);
  m.triangles = {{a, b, c}};
  m.triangleFace = {0};
  const Order2Stats stats = elevateToOrder2(model, m);
  EXPECT_EQ(stats.straightened, 0);
  const Vec3 mid = m.nodes[m.triangleMid[0][0]];
  EXPECT_NEAR(mid.x(), 1, 1e-6);  // (1, 0, 0), not (−1, 0, 0)
  EXPECT_NEAR(mid.y(), 0, 1e-6);
  EXPECT_NEAR(mid.z(), 0, 1e-6);
}
