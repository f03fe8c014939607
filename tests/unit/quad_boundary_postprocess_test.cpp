// Boundary postprocessing of the quad mesh (thesis 4.8.3, BoundaryPostprocess.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesher/quad/BoundaryPostprocess.h"
#include "mesher/quad/MergeConversion.h"
#include "mesher/quad/QuadConversion.h"
#include "mesher/quad/QuadSmoothing.h"
#include "mesher/quad/TriangleTransport.h"
#include "quad_fixtures.h"

namespace {

using aniso::FaceMesh;
using aniso::Vec2;
using namespace aniso::quad;

/// A 3×3 grid of unit quads on [0,3]², the inner vertex (1,1) pulled to (0.6, 0.45): the
/// corner quad at the origin becomes a sliver (scaled Jacobian ≈ 0.1), its neighbours poor.
QuadMesh2d pulledGrid() {
  FaceMesh fm;
  auto id = [](int i, int j) { return j * 4 + i; };
  for (int j = 0; j <= 3; ++j)
    for (int i = 0; i <= 3; ++i) {
      fm.uv.push_back(Vec2(i, j));
      fm.node.push_back(i == 0 || j == 0 || i == 3 || j == 3 ? id(i, j) : -1);
    }
  fm.uv[id(1, 1)] = Vec2(0.6, 0.45);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) fm.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return QuadMesh2d::fromFaceMesh(fm);
}

double shortestEdgeAt(const QuadMesh2d& m, VertexMetrics& metrics, int v) {
  double s = 1e300;
  for (int e = 0; e < m.numElements(); ++e) {
    const int k = m.cornerIndex(e, v);
    if (k == kNone) continue;
    const int n = m.sides(e);
    s = std::min({s, metrics.length(v, m.corners[e][(k + 1) % n]), metrics.length(v, m.corners[e][(k + n - 1) % n])});
  }
  return s;
}

TEST(QuadBoundaryPostprocess, RepairsAPulledCornerQuad) {
  QuadMesh2d m = pulledGrid();
  const auto snap = quadtest::snapshot(m);
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, 0, 3, 3)}), 1.0);
  VertexMetrics metrics(m, *cs);
  const double before = worstBoundaryLayerQuality(m, metrics);
  ASSERT_LT(before, 0.5);
  const BoundaryPostprocessStats st = postprocessBoundaryLayer(m, metrics);
  quadtest::expectValid(m, snap);
  EXPECT_GE(st.candidates, 1);
  EXPECT_GE(st.moved, 1);
  EXPECT_DOUBLE_EQ(st.worstBefore, before);
  EXPECT_DOUBLE_EQ(st.worstAfter, worstBoundaryLayerQuality(m, metrics));
  // The optimum is the regular grid (all scaled Jacobians 1); the search gets close.
  EXPECT_GT(st.worstAfter, 0.9);
}

TEST(QuadBoundaryPostprocess, LeavesGoodLayersAlone) {
  QuadMesh2d m = pulledGrid();
  m.uv[5] = Vec2(1, 1);  // the regular grid
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, 0, 3, 3)}), 1.0);
  VertexMetrics metrics(m, *cs);
  const std::vector<Vec2> uv = m.uv;
  const BoundaryPostprocessStats st = postprocessBoundaryLayer(m, metrics);
  EXPECT_EQ(st.candidates, 0);
  EXPECT_EQ(st.moved, 0);
  EXPECT_EQ(m.uv, uv);
}

TEST(QuadBoundaryPostprocess, KeepsEdgesAboveTheFloor) {
  // A floor of 1.4 (the star's shortest edge, 0.60, times shortestEdge): the pulled vertex's
  // edges to (2,1) and (1,2) (1.50 and 1.60 on entry) may not get shorter than 1.4, which
  // blocks the way to the regular grid (where they are 1), so the vertex stops short of
  // the free optimum while the edges shorter than the floor may grow.
  QuadMesh2d m = pulledGrid();
  const auto snap = quadtest::snapshot(m);
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, 0, 3, 3)}), 1.0);
  VertexMetrics metrics(m, *cs);
  const int pulled = 5;
  ASSERT_FALSE(m.boundary[pulled]);
  const double shortestBefore = shortestEdgeAt(m, metrics, pulled);
  const double before = worstBoundaryLayerQuality(m, metrics);
  BoundaryPostprocessOptions o;
  ASSERT_NEAR(shortestBefore, std::hypot(0.4, 0.45), 1e-12);  // to (1,0): the star's shortest edge
  o.shortestEdge = 1.4 / shortestBefore;
  const BoundaryPostprocessStats st = postprocessBoundaryLayer(m, metrics, o);
  quadtest::expectValid(m, snap);
  EXPECT_GE(shortestEdgeAt(m, metrics, pulled), shortestBefore - 1e-12);
  EXPECT_GE(metrics.length(pulled, 6), 1.4 - 1e-12);  // (2,1)
  EXPECT_GE(metrics.length(pulled, 9), 1.4 - 1e-12);  // (1,2)
  EXPECT_GT(st.worstAfter, before);
  EXPECT_LT(st.worstAfter, 0.9);
}

TEST(QuadBoundaryPostprocess, ConversionRaisesTheWorstBoundaryQuadAndIsDeterministic) {
  const quadtest::HolePlate plate;
  auto run = [&](bool postprocess) {
    FaceMesh fm = plate.fm;
    QuadOptions o;
    o.boundaryPostprocess = postprocess;
    const QuadStats st = convertToQuads(fm, *plate.cs, nullptr, {}, o);
    return std::make_pair(fm, st);
  };
  const auto [without, stWithout] = run(false);
  const auto [with, stWith] = run(true);
  const auto [again, stAgain] = run(true);
  EXPECT_EQ(with.uv, again.uv);
  EXPECT_EQ(with.quads, again.quads);
  EXPECT_EQ(stWithout.boundary.moved, 0);
  EXPECT_GE(stWith.boundary.worstAfter, stWith.boundary.worstBefore);
  // Same topology (the postprocessing only moves vertices).
  EXPECT_EQ(with.quads, without.quads);
  EXPECT_EQ(with.triangles, without.triangles);
  // The worst element of the boundary layer, measured on the written meshes.
  auto worstLayer = [&](const FaceMesh& fm) {
    QuadMesh2d m = QuadMesh2d::fromFaceMesh(fm);
    VertexMetrics metrics(m, *plate.cs);
    return worstBoundaryLayerQuality(m, metrics);
  };
  EXPECT_GE(worstLayer(with), worstLayer(without));
}

}  // namespace
