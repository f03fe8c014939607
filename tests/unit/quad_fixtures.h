#pragma once
// Shared helpers of the quad conversion tests: triangle meshes from the face mesher on
// planar domains (even boundary counts), and the validators every operator test calls:
// structure (QuadMesh2d::validate), geometry (every element strictly convex and
// counter-clockwise), boundary unchanged (the boundary vertices keep their (u, v) and the
// boundary edges stay element edges), area preserved.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "face_mesher_fixtures.h"
#include "mesher/quad/QuadShape.h"
#include "mesher/surface/FaceMesher.h"

namespace quadtest {

using aniso::FaceMesh;
using aniso::Vec2;
using aniso::quad::QuadMesh2d;

/// Boundary nodes at spacing h along each polygon side, one more node on a side when the
/// loop would be odd (so every loop is even).
inline aniso::FaceBoundary evenBoundary(const std::vector<facetest::Polygon>& loops, double h) {
  aniso::FaceBoundary b = facetest::polygonBoundary(loops, h);
  int node = 0;
  for (auto& loop : b.loops) {
    if (loop.size() % 2 == 1) {
      // Split the first segment.
      const Vec2 mid = 0.5 * (loop[0].uv + loop[1].uv);
      loop.insert(loop.begin() + 1, aniso::BoundaryNode{mid, -1});
    }
  }
  for (auto& loop : b.loops)
    for (auto& n : loop) n.node = node++;
  return b;
}

inline aniso::Box2 Box2Of(const std::vector<facetest::Polygon>& loops) {
  aniso::Box2 box;
  for (const auto& p : loops)
    for (const Vec2& x : p) box.add(x);
  box.lo -= Vec2(1, 1);
  box.hi += Vec2(1, 1);
  return box;
}

inline FaceMesh triangleMesh(const std::vector<facetest::Polygon>& loops, double h) {
  const aniso::FaceBoundary b = evenBoundary(loops, h);
  auto cs = facetest::isotropicSpace(Box2Of(loops), h);
  return aniso::meshFace(b, *cs).mesh;
}

inline double area(const QuadMesh2d& m) {
  double a = 0;
  for (int e = 0; e < m.numElements(); ++e) {
    const int n = m.sides(e);
    for (int k = 0; k < n; ++k) {
      const Vec2& p = m.uv[m.corners[e][k]];
      const Vec2& q = m.uv[m.corners[e][(k + 1) % n]];
      a += 0.5 * (p.x() * q.y() - p.y() * q.x());
    }
  }
  return a;
}

/// Undirected boundary edges (vertex pairs) of the mesh.
inline std::set<std::pair<int, int>> boundaryEdges(const QuadMesh2d& m) {
  std::set<std::pair<int, int>> s;
  for (int e = 0; e < m.numElements(); ++e)
    for (int k = 0; k < m.sides(e); ++k)
      if (m.adj[e][k] == aniso::quad::kNone) {
        const int a = m.corners[e][k], b = m.corners[e][(k + 1) % m.sides(e)];
        s.insert({std::min(a, b), std::max(a, b)});
      }
  return s;
}

struct Snapshot {
  std::vector<Vec2> boundaryUv;
  std::set<std::pair<int, int>> edges;
  double area = 0;
};

inline Snapshot snapshot(const QuadMesh2d& m) {
  Snapshot s;
  for (int v = 0; v < m.numVertices(); ++v)
    if (m.boundary[v]) s.boundaryUv.push_back(m.uv[v]);
  s.edges = boundaryEdges(m);
  s.area = area(m);
  return s;
}

/// Valid structure and geometry, boundary as in `before`, same area.
inline void expectValid(const QuadMesh2d& m, const Snapshot& before) {
  EXPECT_EQ(facetest::joined(m.validate()), "");
  EXPECT_EQ(facetest::joined(aniso::quad::validateGeometry(m)), "");
  const Snapshot now = snapshot(m);
  EXPECT_EQ(now.boundaryUv, before.boundaryUv);
  EXPECT_EQ(now.edges, before.edges);
  EXPECT_NEAR(now.area, before.area, 1e-9 * std::abs(before.area));
}

inline int count(const QuadMesh2d& m, int sides) {
  int n = 0;
  for (int e = 0; e < m.numElements(); ++e) n += m.sides(e) == sides;
  return n;
}

/// The 2×1 plate with a round hole meshed isotropically at h = 0.05: the common test face.
struct HolePlate {
  std::vector<facetest::Polygon> loops{facetest::rectangle(0, 0, 2, 1), facetest::circle(aniso::Vec2(0.7, 0.5), 0.25, 40, true)};
  double h = 0.05;
  aniso::FaceMesh fm = triangleMesh(loops, h);
  std::shared_ptr<aniso::CSAnalytic2d> cs = facetest::isotropicSpace(Box2Of(loops), h);
};

}  // namespace quadtest
