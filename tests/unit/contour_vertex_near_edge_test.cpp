// addNodesNearVertices (mesher/surface/contour/VertexNearEdge.h): a hole's corner close to
// a curved outer edge gets a node of that edge next to it, so the discretized loops do not
// cross in (u, v).
#include <gtest/gtest.h>

#include <cmath>

#include "contour_test_models.h"
#include "mesher/surface/ContourDiscretization.h"
#include "mesher/surface/contour/VertexNearEdge.h"

using namespace aniso;
using namespace aniso::test;

namespace {

/// The unit disc with a square hole [0.1, c]² whose corner (c, c) lies `gap` inside the
/// circle (at 45 degrees).
Model discWithSquareHole(double gap) {
  Model m = disc(1.0);
  ModelBuilder b;
  b.m = std::move(m);
  const double c = (1 - gap) / std::sqrt(2.0);
  // a hole walks clockwise
  const std::vector<int> vs = {b.vertex({0.1, 0.1, 0}), b.vertex({0.1, c, 0}), b.vertex({c, c, 0}), b.vertex({c, 0.1, 0})};
  polygonLoop(b, 0, vs, false);
  return b.m;
}

bool inside(const std::vector<BoundaryNode>& loop, const Vec2& p) {
  bool in = false;
  for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Vec2 &a = loop[i].uv, &c = loop[j].uv;
    if ((a.y() > p.y()) != (c.y() > p.y()) && p.x() < (c.x() - a.x()) * (p.y() - a.y()) / (c.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

}  // namespace

TEST(VertexNearEdge, AHoleCornerNearTheRimGetsARimNodeBesideIt) {
  const double gap = 0.002;
  const Model m = discWithSquareHole(gap);
  std::unique_ptr<CSAnalytic2d> cs = space(m, 0, isotropic(0.3));
  const std::vector<const ControlSpace2d*> spaces = {cs.get()};
  // the circle alone: 21 segments of 17 degrees, the chord at 45 degrees 0.011 inside the
  // circle, past the corner
  std::vector<std::vector<double>> t(m.edges.size());
  t[0].resize(22);
  for (int k = 0; k <= 21; ++k) t[0][k] = 2 * kPi * k / 21;
  EXPECT_EQ(contour::addNodesNearVertices(m, spaces, t), 1);
  ASSERT_EQ(t[0].size(), 23u);
  bool at45 = false;
  for (const double x : t[0]) at45 = at45 || std::abs(x - kPi / 4) < 1e-6;
  EXPECT_TRUE(at45);
  // through discretizeEdges: the hole's corner inside the outer loop
  SurfaceMesh mesh;
  const std::vector<EdgeDiscretization> edges = discretizeEdges(m, spaces, {}, mesh);
  const FaceBoundary fb = faceBoundary(m, 0, edges, mesh);
  ASSERT_EQ(fb.loops.size(), 2u);
  const double c = (1 - gap) / std::sqrt(2.0);
  EXPECT_TRUE(inside(fb.loops[0], Vec2(c, c)));
  // no corner near the rim: nothing added
  const Model far = discWithSquareHole(0.3);
  std::vector<std::vector<double>> t2(far.edges.size());
  t2[0] = t[0];
  t2[0].erase(std::find_if(t2[0].begin(), t2[0].end(), [](double x) { return std::abs(x - kPi / 4) < 1e-6; }));
  EXPECT_EQ(contour::addNodesNearVertices(far, spaces, t2), 0);
}

TEST(VertexNearEdge, ACornerOnTheEdgeItselfIsLeft) {
  // the corner exactly on the circle (the loops touch): a node there would coincide with it
  const Model m = discWithSquareHole(0.0);
  std::unique_ptr<CSAnalytic2d> cs = space(m, 0, isotropic(0.3));
  std::vector<std::vector<double>> t(m.edges.size());
  for (int k = 0; k <= 21; ++k) t[0].push_back(2 * kPi * k / 21);
  EXPECT_EQ(contour::addNodesNearVertices(m, {cs.get()}, t), 0);
}
