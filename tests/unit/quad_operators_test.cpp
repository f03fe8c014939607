// The operators of the quad conversion one by one, each followed by the validators
// (structure, strictly convex counter-clockwise elements, boundary and area unchanged):
// odd-cycle splits, triangle transport, topological transformations, smoothing.
#include <gtest/gtest.h>

#include "mesher/quad/DiagonalCollapse.h"
#include "mesher/quad/HexagonSplit.h"
#include "mesher/quad/MergeConversion.h"
#include "mesher/quad/OddSplit.h"
#include "mesher/quad/PairSplit.h"
#include "mesher/quad/QuadSmoothing.h"
#include "mesher/quad/QuadTopology.h"
#include "mesher/quad/RegionParity.h"
#include "mesher/quad/TriangleTransport.h"
#include "quad_fixtures.h"

namespace {

using namespace aniso;
using namespace aniso::quad;
using quadtest::count;

using Fixture = quadtest::HolePlate;

/// Applies `split` to the first 20 triangle pairs that accept it, then validates.
template <class Split>
void checkSplits(Split split) {
  Fixture f;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(f.fm);
  const auto snap = quadtest::snapshot(m);
  VertexMetrics metrics(m, *f.cs);
  int done = 0;
  for (int t = 0; t < m.numElements() && done < 20; ++t)
    for (int j = 0; j < 3 && m.isTriangle(t); ++j)
      if (split(m, metrics, t, j)) ++done;
  EXPECT_EQ(done, 20);
  quadtest::expectValid(m, snap);
  EXPECT_EQ(count(m, 4), 20);
  EXPECT_EQ(m.numVertices(), static_cast<int>(f.fm.uv.size()) + 20);
}

TEST(QuadOddSplit, CentroidSplitKeepsMeshValid) {
  checkSplits([](QuadMesh2d& m, VertexMetrics& mt, int t, int j) { return splitAndMerge(m, mt, t, j, 0.2).done; });
}

TEST(QuadOddSplit, EdgeSplitKeepsMeshValid) {
  checkSplits([](QuadMesh2d& m, VertexMetrics& mt, int t, int j) {
    return splitEdgeAndMerge(m, mt, t, (j + 1) % 3, j, 0.2).done;
  });
}

TEST(QuadOddSplit, ParityDetectsOddPieces) {
  // A strip of 6 triangles (3 squares cut by diagonals), adjacent in the chain
  // 1-0-3-2-5-4: removing the pair (3, 2) leaves 2 + 2 triangles (even), the pair (0, 3)
  // leaves 1 + 3 (odd), the end pair (0, 1) one piece.
  FaceMesh fm;
  for (int i = 0; i <= 3; ++i) {
    fm.uv.push_back(Vec2(i, 0));
    fm.uv.push_back(Vec2(i, 1));
  }
  fm.node.assign(fm.uv.size(), 0);
  for (int i = 0; i < 8; ++i) fm.node[i] = i;
  for (int i = 0; i < 3; ++i) {
    const int a = 2 * i, b = 2 * i + 2, c = 2 * i + 3, d = 2 * i + 1;
    fm.triangles.push_back({a, b, c});
    fm.triangles.push_back({a, c, d});
  }
  const QuadMesh2d m = QuadMesh2d::fromFaceMesh(fm);
  RegionParity parity;
  EXPECT_TRUE(parity.mergeKeepsParity(m, 3, 2));
  EXPECT_FALSE(parity.mergeKeepsParity(m, 0, 3));
  EXPECT_TRUE(parity.mergeKeepsParity(m, 0, 1));
}

TEST(QuadTransport, PairsLeftTrianglesAndStaysValid) {
  Fixture f;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(f.fm);
  const auto snap = quadtest::snapshot(m);
  VertexMetrics metrics(m, *f.cs);
  mergeFront(m, metrics);
  const int before = count(m, 3);
  const TransportStats st = pairTriangles(m, metrics);
  quadtest::expectValid(m, snap);
  EXPECT_EQ(count(m, 3), before - 2 * st.paired);
  EXPECT_GT(st.paired, 0);
  EXPECT_LT(count(m, 3), before / 2);
}

TEST(QuadTopology, SwapsAndDoubletsStayValid) {
  Fixture f;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(f.fm);
  const auto snap = quadtest::snapshot(m);
  VertexMetrics metrics(m, *f.cs);
  mergeFront(m, metrics);
  const int quads = count(m, 4), tris = count(m, 3);
  const TopologyStats st = improveTopology(m, metrics);
  quadtest::expectValid(m, snap);
  EXPECT_EQ(count(m, 4), quads - st.doublets - st.collapses);
  EXPECT_EQ(count(m, 3), tris);
}

TEST(QuadTopology, RemovesADoublet) {
  // Two quads sharing two edges at an inner vertex of degree 2 become one.
  FaceMesh fm;
  fm.uv = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(0, 2), Vec2(1.1, 0.9)};
  fm.node = {0, 1, 2, 3, -1};
  fm.quads = {{4, 3, 0, 1}, {4, 1, 2, 3}};
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(fm);
  const auto snap = quadtest::snapshot(m);
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, 0, 2, 2)}), 1.0);
  VertexMetrics metrics(m, *cs);
  const TopologyStats st = improveTopology(m, metrics);
  EXPECT_EQ(st.doublets, 1);
  quadtest::expectValid(m, snap);
  EXPECT_EQ(count(m, 4), 1);
}

TEST(QuadSmoothing, ImprovesWorstAndStaysValid) {
  Fixture f;
  QuadMesh2d m = QuadMesh2d::fromFaceMesh(f.fm);
  const auto snap = quadtest::snapshot(m);
  VertexMetrics metrics(m, *f.cs);
  mergeFront(m, metrics);
  pairTriangles(m, metrics);
  auto worst = [&] {
    double w = 1;
    for (int e = 0; e < m.numElements(); ++e)
      if (m.isQuad(e)) w = std::min(w, elementQuality(m, metrics, m.corners[e]));
    return w;
  };
  const double before = worst();
  const SmoothStats st = smoothQuadMesh(m, metrics);
  quadtest::expectValid(m, snap);
  EXPECT_GT(st.moved, 0);
  EXPECT_GE(worst(), before);
}

}  // namespace

namespace {

/// Two triangles with a non-convex union (reflex at vertex 1): merging would give an
/// invalid quad.
aniso::quad::QuadMesh2d reflexPair() {
  aniso::FaceMesh fm;
  fm.uv = {aniso::Vec2(0, 0), aniso::Vec2(1, 0.2), aniso::Vec2(2, 0), aniso::Vec2(1, 1)};
  fm.node = {0, 1, 2, 3};
  fm.triangles = {{0, 1, 3}, {1, 2, 3}};
  return aniso::quad::QuadMesh2d::fromFaceMesh(fm);
}

TEST(QuadPairSplit, TwoTrianglesBecomeFiveQuads) {
  aniso::quad::QuadMesh2d m = reflexPair();
  const auto snap = quadtest::snapshot(m);
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, 0, 2, 1)}), 1.0);
  aniso::quad::VertexMetrics metrics(m, *cs);
  ASSERT_TRUE(aniso::quad::splitPairIntoQuads(m, metrics, 0, 1, 0.1));
  quadtest::expectValid(m, snap);
  EXPECT_EQ(quadtest::count(m, 4), 5);
  EXPECT_EQ(quadtest::count(m, 3), 0);
}

TEST(QuadHexagonSplit, PairAtFlatBoundaryVertexAndSharpCornerBecomesQuads) {
  // A 10° wedge, one element wide: the tip triangle (0, 1, 5) and the triangle (1, 4, 5)
  // meet at vertex 5, a straight-boundary vertex, and the quad (1, 2, 3, 4) is next to
  // them. Merging the pair gives a flat corner at 5; the five-quad split halves the 10°
  // corner (scaled Jacobian sin 5° < 0.1). The hexagon 0..5 takes four quads.
  const double a = 10.0 * 3.14159265358979323846 / 180.0;
  const auto upper = [&](double r) { return aniso::Vec2(r * std::cos(a), r * std::sin(a)); };
  aniso::FaceMesh fm;
  fm.uv = {aniso::Vec2(0, 0), aniso::Vec2(0.8, 0), aniso::Vec2(1.6, 0), upper(1.8), upper(1.2), upper(0.6)};
  fm.node = {0, 1, 2, 3, 4, 5};
  fm.triangles = {{0, 1, 5}, {1, 4, 5}};
  fm.quads = {{1, 2, 3, 4}};
  aniso::quad::QuadMesh2d m = aniso::quad::QuadMesh2d::fromFaceMesh(fm);
  ASSERT_EQ(facetest::joined(m.validate()), "");
  const auto snap = quadtest::snapshot(m);
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, 0, 2, 1)}), 1.0);
  aniso::quad::VertexMetrics metrics(m, *cs);
  const int t1 = 0, t2 = 1;  // fromFaceMesh keeps the order: triangles first
  ASSERT_TRUE(m.isTriangle(t1) && m.isTriangle(t2));
  EXPECT_FALSE(aniso::quad::splitPairIntoQuads(m, metrics, t1, t2, 0.1));
  ASSERT_TRUE(aniso::quad::splitPairWithQuad(m, metrics, t1, t2, 0.1));
  quadtest::expectValid(m, snap);
  EXPECT_EQ(quadtest::count(m, 4), 4);
  EXPECT_EQ(quadtest::count(m, 3), 0);
  EXPECT_EQ(m.numVertices(), 8);
  for (int e = 0; e < m.numElements(); ++e) {
    if (m.isQuad(e)) {
      EXPECT_GE(aniso::quad::elementQuality(m, metrics, m.corners[e]), 0.1);
    }
  }
}

TEST(QuadHexagonSplit, NoQuadNextToThePairLeavesTheMeshUnchanged) {
  aniso::quad::QuadMesh2d m = reflexPair();
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(0, 0, 2, 1)}), 1.0);
  aniso::quad::VertexMetrics metrics(m, *cs);
  EXPECT_FALSE(aniso::quad::splitPairWithQuad(m, metrics, 0, 1, 0.1));
  EXPECT_EQ(quadtest::count(m, 3), 2);
  EXPECT_EQ(m.numVertices(), 4);
}

TEST(QuadDiagonalCollapse, AQuadBetweenTwoValenceThreeVerticesIsRemoved) {
  // Quad (0, 1, 2, 3) with inner corners 0 and 2 of three quads each, 1 and 3 on the
  // boundary: 0 and 2 merge at their midpoint, the four other quads remain.
  aniso::FaceMesh fm;
  fm.uv = {aniso::Vec2(-0.5, 0), aniso::Vec2(0, -0.4), aniso::Vec2(0.5, 0), aniso::Vec2(0, 0.4), aniso::Vec2(-1.5, 0),
           aniso::Vec2(-1, 1),   aniso::Vec2(-1, -1),  aniso::Vec2(1.5, 0), aniso::Vec2(1, 1),   aniso::Vec2(1, -1)};
  fm.node = {-1, 1, -1, 3, 4, 5, 6, 7, 8, 9};
  fm.quads = {{0, 1, 2, 3}, {0, 3, 5, 4}, {0, 4, 6, 1}, {2, 7, 8, 3}, {2, 1, 9, 7}};
  aniso::quad::QuadMesh2d m = aniso::quad::QuadMesh2d::fromFaceMesh(fm);
  ASSERT_EQ(facetest::joined(m.validate()), "");
  ASSERT_EQ(facetest::joined(aniso::quad::validateGeometry(m)), "");
  const auto snap = quadtest::snapshot(m);
  const auto cs = facetest::isotropicSpace(quadtest::Box2Of({facetest::rectangle(-2, -2, 2, 2)}), 1.0);
  aniso::quad::VertexMetrics metrics(m, *cs);
  EXPECT_EQ(aniso::quad::collapseDiagonals(m, metrics, 0.3), 1);
  quadtest::expectValid(m, snap);
  EXPECT_EQ(quadtest::count(m, 4), 4);
  EXPECT_EQ(m.uv[0], aniso::Vec2(0, 0));
  // Nothing left to collapse: the merged vertex has four quads.
  EXPECT_EQ(aniso::quad::collapseDiagonals(m, metrics, 0.3), 0);
}

}  // namespace
