// contour/CuspNodes (matched nodes across the sliver at a sharp corner, for quad meshes)
// and contour/CornerParity's corner list across a pole (a degenerate edge between two
// edges makes one corner of them).
#include <gtest/gtest.h>

#include <cmath>

#include "contour_test_models.h"
#include "mesher/surface/contour/CornerParity.h"
#include "mesher/surface/contour/CuspNodes.h"

using namespace aniso;
using namespace aniso::test;

namespace {

/// The triangle (0,0), (10,0), (10, 10 tan a) of the plane z = 0, corner a at the origin;
/// edges 0: origin → (10,0), 1: up, 2: (10,h) → origin. With `pole`, a degenerate edge at
/// the origin closes the loop between edges 2 and 0.
Model wedge(double angleDeg, bool pole = false) {
  ModelBuilder b;
  const double h = 10 * std::tan(angleDeg * kPi / 180);
  const int f = b.face(xyPlane(-1, 30, -1, 30), box(0, 0, 10, h));
  const std::vector<int> vs = {b.vertex({0, 0, 0}), b.vertex({10, 0, 0}), b.vertex({10, h, 0})};
  polygonLoop(b, f, vs, true);
  if (pole) {
    const int d = b.degenerate(vs[0], 0, 1);
    const int k = b.pcurve(d, f, std::make_shared<Line2d>(Vec2(0, 0), Vec2(0, 0)));
    b.m.faces[f].loops[0].uses.push_back({d, false, k});
  }
  return b.m;
}

std::vector<double> uniform(int n) {
  std::vector<double> t(n + 1);
  for (int i = 0; i <= n; ++i) t[i] = static_cast<double>(i) / n;
  return t;
}

double distanceFromOrigin(const Model& m, int e, double t) { return m.edges[e].curve->point(t).norm(); }

}  // namespace

TEST(CornerParity, APoleBetweenTwoEdgesIsOneCorner) {
  EXPECT_EQ(contour::sharpCorners(wedge(3, true), 0), 1);
  EXPECT_EQ(contour::sharpCorners(wedge(10, true), 0), 0);
  const std::vector<contour::LoopCorner> c = contour::sharpCornerList(wedge(3, true), 0);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].in, 2);   // edge 2 arrives at the origin,
  EXPECT_EQ(c[0].out, 0);  // edge 0 leaves it; the pole (use 3) between them is skipped
  // A sphere's seam back to itself around either pole is no corner.
  EXPECT_EQ(contour::sharpCorners(sphere(), 0), 0);
}

TEST(CuspNodes, NodesFaceEachOtherAcrossTheSliver) {
  for (const bool pole : {false, true}) {
    const Model m = wedge(3, pole);
    const auto cs = space(m, 0, isotropic(0.5));
    // Edge 0 in 20 pieces, edge 2 in 19: apart from the corner, no node faces another.
    std::vector<std::vector<double>> t(m.edges.size());
    t[0] = uniform(20);
    t[1] = uniform(2);
    t[2] = uniform(19);
    const std::vector<std::vector<double>> before = t;
    const int moved = contour::matchCuspNodes(m, {cs.get()}, t);
    EXPECT_GT(moved, 0) << pole;
    EXPECT_EQ(moved % 2, 0);
    ASSERT_EQ(t[0].size(), before[0].size());
    ASSERT_EQ(t[2].size(), before[2].size());
    EXPECT_EQ(t[1], before[1]);
    for (int e : {0, 2})
      for (std::size_t i = 1; i < t[e].size(); ++i) EXPECT_LT(t[e][i - 1], t[e][i]) << e << " " << i;
    // Node k from the origin: t[0][k] and t[2][19 - k], at the same distance from it.
    const int pairs = moved / 2;
    EXPECT_GE(pairs, 5);  // the sliver (width 0.05 s) reaches past the middle of the edges
    for (int k = 1; k <= pairs; ++k)
      EXPECT_NEAR(distanceFromOrigin(m, 0, t[0][k]), distanceFromOrigin(m, 2, t[2][19 - k]), 1e-9) << k;
    // The far halves keep their nodes.
    for (int k = 10; k <= 20; ++k) EXPECT_EQ(t[0][k], before[0][k]) << k;
    for (int k = 0; k <= 9; ++k) EXPECT_EQ(t[2][k], before[2][k]) << k;
  }
}

TEST(CuspNodes, ABluntCornerIsLeftAlone) {
  const Model m = wedge(30);
  const auto cs = space(m, 0, isotropic(0.5));
  std::vector<std::vector<double>> t{uniform(20), uniform(10), uniform(19)};
  const auto before = t;
  EXPECT_EQ(contour::matchCuspNodes(m, {cs.get()}, t), 0);
  EXPECT_EQ(t, before);
}
