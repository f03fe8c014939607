// Tests of the face mesher's operators (mesher/surface/face/): boundary triangulation, edge
// recovery, outside removal, refinement, the visible walk, the metric helpers and the face
// mesh validator. del2d::validate() runs after every operator.
#include <gtest/gtest.h>

#include <iostream>
#include <numbers>
#include <random>

#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/Validate2d.h"
#include "mesher/surface/face/BoundaryTriangulation.h"
#include "mesher/surface/face/DomainRemoval.h"
#include "mesher/surface/face/EdgeRecovery.h"
#include "mesher/surface/face/FaceMetric.h"
#include "mesher/surface/face/FrontalPoint.h"
#include "mesher/surface/face/Refinement.h"
#include "mesher/surface/face/ValidateFaceMesh.h"
#include "mesher/surface/face/VisibleWalk.h"
#include "mesher/surface/improve/ImproveFace.h"
#include "tests/unit/face_mesher_fixtures.h"

using namespace aniso;
using namespace aniso::face;
using namespace facetest;
using del2d::TriId;
using del2d::VertexId;

namespace {

Box2 boxOf(double x0, double y0, double x1, double y1) {
  Box2 b;
  b.add(Vec2(x0, y0));
  b.add(Vec2(x1, y1));
  return b;
}

#define EXPECT_TRI_VALID(tri, opts)                      \
  do {                                                   \
    const auto problems_ = del2d::validate(tri, opts);   \
    EXPECT_TRUE(problems_.empty()) << joined(problems_); \
  } while (0)

bool hasEdge(const del2d::Triangulation2d& tri, VertexId a, VertexId b) {
  TriId t;
  int i = 0;
  return tri.findEdge(a, b, t, i) || tri.findEdge(b, a, t, i);
}

TEST(FaceMetric, QualityOfTheUnitTriangleIsOne) {
  const Mat2 m = Mat2::Identity();
  const Vec2 a(0, 0), b(1, 0), c(0.5, std::sqrt(3.0) / 2);
  EXPECT_NEAR(triangleQuality(m, a, b, c), 1.0, 1e-14);
  // Twice the size: circumcircle area × 4.
  EXPECT_NEAR(triangleQuality(m, a, 2 * b, 2 * c), 0.25, 1e-14);
  // The same triangle under a metric that halves lengths along x and y.
  EXPECT_NEAR(triangleQuality(Mat2::Identity() * 0.5, a, 2 * b, 2 * c), 1.0, 1e-14);
  EXPECT_EQ(triangleQuality(m, a, b, Vec2(2, 0)), 0.0);  // degenerate
  EXPECT_EQ(triangleQuality(m, a, c, b), 0.0);           // clockwise
  // Anisotropic: the unit triangle stretched by M⁻¹ is perfect in M.
  const Mat2 aniso = Metric2d::fromAngle(0.3, 0.01, 0.2).matrix();
  const Mat2 inv = aniso.inverse();
  EXPECT_NEAR(triangleQuality(aniso, inv * a, inv * b, inv * c), 1.0, 1e-12);
  EXPECT_NEAR(metricArea(aniso, inv * a, inv * b, inv * c), kIdealTriangleArea, 1e-12);
}

TEST(FaceMetric, CircumcenterInMetricSpace) {
  const Mat2 m = Metric2d::fromAngle(0.7, 0.05, 0.4).matrix();
  const Vec2 a(0.1, 0.2), b(0.5, 0.1), c(0.3, 0.6);
  Vec2 o;
  ASSERT_TRUE(metricCircumcenter(m, a, b, c, o));
  const double ra = (m * (a - o)).norm(), rb = (m * (b - o)).norm(), rc = (m * (c - o)).norm();
  EXPECT_NEAR(ra, rb, 1e-12 * ra);
  EXPECT_NEAR(ra, rc, 1e-12 * ra);
  EXPECT_FALSE(metricCircumcenter(m, a, b, a + 2 * (b - a), o));
}

TEST(FaceOperators, BoundaryTriangulationInsertsEveryNode) {
  const auto cs = an1Space(8);
  const FaceBoundary b = metricBoundary({rectangle(0, 0, 2, 1)}, *cs, 1000);
  const FlatBoundary flat = flattenBoundary(b);
  BoundaryTriangulation bt = triangulateBoundary(flat, *cs, 7);
  EXPECT_TRUE(bt.problems.empty()) << joined(bt.problems);
  EXPECT_TRI_VALID(bt.tri, del2d::ValidateOptions{});
  for (std::size_t k = 0; k < flat.size(); ++k) {
    ASSERT_TRUE(bt.vertexOf[k].valid());
    EXPECT_EQ(bt.tri.point(bt.vertexOf[k]), flat.uv[k]);
  }
  // Constant metric: the result is the Delaunay triangulation in that metric.
  const auto iso = isotropicSpace(boxOf(0, 0, 2, 1), 0.1);
  BoundaryTriangulation bt2 = triangulateBoundary(flat, *iso, 7);
  del2d::ValidateOptions vo;
  vo.delaunay = true;
  vo.transform = Mat2::Identity() * 10;
  EXPECT_TRI_VALID(bt2.tri, vo);
}

TEST(FaceOperators, RecoverEdgeByFlips) {
  // Points on two rows; the long segment between the ends of the bottom row crosses the
  // edges to the top row once the bottom row's middle nodes are absent.
  Box2 box = boxOf(0, -1, 4, 1);
  del2d::Triangulation2d tri(box);
  const VertexId a = del2d::insertPoint(tri, Vec2(0, 0)).vertex;
  const VertexId b = del2d::insertPoint(tri, Vec2(4, 0)).vertex;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> ux(0.2, 3.8), uy(-0.4, 0.4);
  for (int i = 0; i < 60; ++i) {
    double y = uy(rng);
    if (std::abs(y) < 0.01) y = 0.05;
    del2d::insertPoint(tri, Vec2(ux(rng), y));
  }
  ASSERT_FALSE(hasEdge(tri, a, b));
  const EdgeRecovery r = recoverEdge(tri, a, b);
  EXPECT_EQ(r.status, RecoveryStatus::Recovered);
  EXPECT_GT(r.crossings, 1u);
  EXPECT_TRUE(hasEdge(tri, a, b));
  EXPECT_TRI_VALID(tri, del2d::ValidateOptions{});
  EXPECT_EQ(recoverEdge(tri, a, b).status, RecoveryStatus::Present);
}

TEST(FaceOperators, RecoverEdgeReportsBlockers) {
  del2d::Triangulation2d tri(boxOf(0, -1, 4, 1));
  const VertexId a = del2d::insertPoint(tri, Vec2(0, 0)).vertex;
  const VertexId b = del2d::insertPoint(tri, Vec2(4, 0)).vertex;
  const VertexId c = del2d::insertPoint(tri, Vec2(2, -0.5)).vertex;
  const VertexId d = del2d::insertPoint(tri, Vec2(2, 0.5)).vertex;
  const VertexId on = del2d::insertPoint(tri, Vec2(1, 0)).vertex;
  // c–d is an edge crossing a–b: constrain it.
  ASSERT_TRUE(tri.setConstrainedEdge(c, d));
  const auto rev = tri.revision();
  EdgeRecovery r = recoverEdge(tri, a, b);
  EXPECT_EQ(r.status, RecoveryStatus::VertexOnSegment);
  EXPECT_EQ(r.blocker, on);
  EXPECT_EQ(tri.revision(), rev);  // nothing changed
  r = recoverEdge(tri, on, b);
  EXPECT_EQ(r.status, RecoveryStatus::CrossesConstrained);
  EXPECT_TRUE((r.crossA == c && r.crossB == d) || (r.crossA == d && r.crossB == c));
  EXPECT_EQ(tri.revision(), rev);
  EXPECT_TRI_VALID(tri, del2d::ValidateOptions{});
}

TEST(FaceOperators, PipelineKeepsTheTriangulationValid) {
  const double h = 0.05;
  const auto cs = isotropicSpace(boxOf(0, 0, 1, 1), h);
  const Polygon hole = circle(Vec2(0.6, 0.4), 0.15, 24, true);
  const FaceBoundary b = polygonBoundary({rectangle(0, 0, 1, 1), hole}, h);
  const FlatBoundary flat = flattenBoundary(b);
  BoundaryTriangulation bt = triangulateBoundary(flat, *cs, 1);
  ASSERT_TRUE(bt.problems.empty());
  del2d::Triangulation2d& tri = bt.tri;
  BoundaryRecoveryStats rs;
  const auto rec = recoverBoundaryEdges(tri, flat, bt.vertexOf, *cs, &rs);
  EXPECT_TRUE(rec.empty()) << joined(rec);
  EXPECT_TRI_VALID(tri, del2d::ValidateOptions{});
  for (std::uint32_t k = 0; k < flat.size(); ++k) {
    TriId t;
    int i = 0;
    ASSERT_TRUE(tri.findEdge(bt.vertexOf[k], bt.vertexOf[flat.next[k]], t, i));
    EXPECT_TRUE(tri.isConstrained(t, i));
  }
  std::size_t removed = 0;
  const auto rem = removeOutside(tri, flat, bt.vertexOf, &removed);
  EXPECT_TRUE(rem.empty()) << joined(rem);
  EXPECT_GT(removed, 0u);
  EXPECT_TRI_VALID(tri, del2d::ValidateOptions{});
  const RefineStats st = refineFace(tri, *cs);
  EXPECT_GT(st.inserted, 100u);
  EXPECT_GT(st.frontal, st.inserted / 2);  // the frontal phase places most points
  EXPECT_FALSE(st.limitReached);
  EXPECT_GT(st.predictedTriangles, 500.0);
  // Constant metric and empty-circle insertions: constrained Delaunay in that metric.
  del2d::ValidateOptions vo;
  vo.delaunay = true;
  vo.transform = Mat2::Identity() / h;
  EXPECT_TRI_VALID(tri, vo);
  // Every triangle is good or could not be refined by the cancellation rules.
  std::size_t bad = 0, live = 0;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!tri.isAlive(t)) continue;
    ++live;
    const Vec2& p0 = tri.point(tri.vertex(t, 0));
    const Vec2& p1 = tri.point(tri.vertex(t, 1));
    const Vec2& p2 = tri.point(tri.vertex(t, 2));
    bad += triangleQuality(Mat2::Identity() / h, p0, p1, p2) < 0.58;
  }
  EXPECT_LT(bad, live / 20);
  // The last pipeline step keeps the triangulation valid and the boundary constrained.
  std::vector<std::uint8_t> fixed(tri.numVertices(), 0);
  for (const VertexId v : bt.vertexOf) fixed[v.index] = 1;
  improveFaceMesh(tri, *cs, fixed);
  EXPECT_TRI_VALID(tri, del2d::ValidateOptions{});
  for (std::uint32_t k = 0; k < flat.size(); ++k) {
    TriId t;
    int i = 0;
    ASSERT_TRUE(tri.findEdge(bt.vertexOf[k], bt.vertexOf[flat.next[k]], t, i));
    EXPECT_TRUE(tri.isConstrained(t, i));
    EXPECT_EQ(tri.point(bt.vertexOf[k]), flat.uv[k]);
  }
}

TEST(FaceOperators, FrontalPointMakesTheUnitTriangle) {
  Vec2 p(-1, -1);
  // A tall triangle on a unit front edge: the apex of the unit equilateral triangle.
  ASSERT_TRUE(frontalPoint(Mat2::Identity(), Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 3), p));
  EXPECT_NEAR(p.x(), 0.5, 1e-12);
  EXPECT_NEAR(p.y(), std::sqrt(3.0) / 2, 1e-12);
  // The same in a metric 10 times finer across the edge: the point is 10 times closer.
  Mat2 m = Mat2::Identity();
  m(1, 1) = 10;
  ASSERT_TRUE(frontalPoint(m, Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 0.3), p));
  EXPECT_NEAR(p.x(), 0.5, 1e-12);
  EXPECT_NEAR(p.y(), std::sqrt(3.0) / 20, 1e-12);
  // The point stays inside K's circumcircle (centre (0.5, 0.11/1.2), through the apex).
  ASSERT_TRUE(frontalPoint(Mat2::Identity(), Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 0.6), p));
  const Vec2 centre(0.5, (0.36 - 0.25) / 1.2);
  EXPECT_LT((p - centre).norm(), 0.6 - centre.y());
  EXPECT_NEAR(p.x(), 0.5, 1e-12);
  // A point on the far side of the edge (c below) gives a point below.
  ASSERT_TRUE(frontalPoint(Mat2::Identity(), Vec2(0, 0), Vec2(1, 0), Vec2(0.5, -3), p));
  EXPECT_NEAR(p.y(), -std::sqrt(3.0) / 2, 1e-12);
  // Obtuse at c (circumcentre behind the front edge) and degenerate triangles: refused.
  const Vec2 before = p;
  EXPECT_FALSE(frontalPoint(Mat2::Identity(), Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 0.2), p));
  EXPECT_FALSE(frontalPoint(Mat2::Identity(), Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), p));
  EXPECT_FALSE(frontalPoint(Mat2::Zero(), Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 3), p));
  EXPECT_EQ(p, before);
}

TEST(FaceOperators, FrontalRefinementIsMoreRegular) {
  // The same uniform square with and without the frontal phase, then improved as the
  // face mesher does: valid either way, and the frontal mesh has the better mean and
  // worst shape (the reason it is the default).
  const double h = 0.02;
  const auto cs = isotropicSpace(boxOf(0, 0, 1, 1), h);
  const FaceBoundary b = polygonBoundary({rectangle(0, 0, 1, 1)}, h);
  const FlatBoundary flat = flattenBoundary(b);
  auto run = [&](bool frontal, double& mean, double& worst) {
    BoundaryTriangulation bt = triangulateBoundary(flat, *cs, 1);
    EXPECT_TRUE(recoverBoundaryEdges(bt.tri, flat, bt.vertexOf, *cs).empty());
    EXPECT_TRUE(removeOutside(bt.tri, flat, bt.vertexOf).empty());
    RefineOptions ro;
    ro.frontal = frontal;
    const RefineStats st = refineFace(bt.tri, *cs, ro);
    EXPECT_FALSE(st.limitReached);
    EXPECT_TRI_VALID(bt.tri, del2d::ValidateOptions{});
    std::vector<std::uint8_t> fixed(bt.tri.numVertices(), 0);
    for (const VertexId v : bt.vertexOf) fixed[v.index] = 1;
    for (const VertexId v : bt.tri.corners()) fixed[v.index] = 1;
    improveFaceMesh(bt.tri, *cs, fixed);
    EXPECT_TRI_VALID(bt.tri, del2d::ValidateOptions{});
    double sum = 0;
    std::size_t n = 0;
    worst = 1;
    for (std::uint32_t k = 0; k < bt.tri.triangleSlots(); ++k) {
      const TriId t(k);
      if (!bt.tri.isAlive(t)) continue;
      // Shape only (the Euclidean mean ratio): scale out the size.
      const Vec2 &p0 = bt.tri.point(bt.tri.vertex(t, 0)), &p1 = bt.tri.point(bt.tri.vertex(t, 1)),
                 &p2 = bt.tri.point(bt.tri.vertex(t, 2));
      const double area = 0.5 * cross2(p1 - p0, p2 - p0);
      const double l2 = (p1 - p0).squaredNorm() + (p2 - p1).squaredNorm() + (p0 - p2).squaredNorm();
      const double eta = 4 * std::sqrt(3.0) * area / l2;
      sum += eta;
      ++n;
      worst = std::min(worst, eta);
    }
    mean = sum / static_cast<double>(n);
    return st;
  };
  double meanF = 0, worstF = 0, meanM = 0, worstM = 0;
  const RefineStats sf = run(true, meanF, worstF);
  const RefineStats sm = run(false, meanM, worstM);
  EXPECT_GT(sf.frontal, 0u);
  EXPECT_EQ(sm.frontal, 0u);
  EXPECT_GT(sm.ccs, 0u);
  EXPECT_GT(sm.mle, 0u);
  EXPECT_GT(meanF, meanM);
  EXPECT_GT(meanF, 0.98);
  EXPECT_GE(worstF, worstM);
  std::cout << "frontal: mean " << meanF << " worst " << worstF << "; MLE/CCS: mean " << meanM << " worst " << worstM
            << "\n";
}

TEST(FaceOperators, RefinementStopsAtTheInsertionLimit) {
  const auto cs = isotropicSpace(boxOf(0, 0, 1, 1), 0.01);
  const FaceBoundary b = polygonBoundary({rectangle(0, 0, 1, 1)}, 0.01);
  const FlatBoundary flat = flattenBoundary(b);
  BoundaryTriangulation bt = triangulateBoundary(flat, *cs, 1);
  ASSERT_TRUE(recoverBoundaryEdges(bt.tri, flat, bt.vertexOf, *cs).empty());
  ASSERT_TRUE(removeOutside(bt.tri, flat, bt.vertexOf).empty());
  RefineOptions ro;
  ro.insertionLimitFactor = 0;
  ro.insertionLimitExtra = 50;
  const RefineStats st = refineFace(bt.tri, *cs, ro);
  EXPECT_TRUE(st.limitReached);
  EXPECT_EQ(st.inserted, 50u);
  EXPECT_TRI_VALID(bt.tri, del2d::ValidateOptions{});
}

TEST(FaceOperators, RefinementPredictsTheFinalCount) {
  // Thesis 6.5: eq. 6.2 first (a rough estimate), then eq. 6.1 while refining, which must
  // approach the final count (fig. 6.16: within a few percent in 2D).
  const double h = 0.01;
  const auto cs = isotropicSpace(boxOf(0, 0, 1, 1), h);
  const FaceBoundary b = polygonBoundary({rectangle(0, 0, 1, 1)}, h);
  const FlatBoundary flat = flattenBoundary(b);
  BoundaryTriangulation bt = triangulateBoundary(flat, *cs, 1);
  ASSERT_TRUE(recoverBoundaryEdges(bt.tri, flat, bt.vertexOf, *cs).empty());
  ASSERT_TRUE(removeOutside(bt.tri, flat, bt.vertexOf).empty());
  std::vector<double> predictions;
  RefineOptions ro;
  ro.predictionInterval = 1000;
  ro.onPrediction = [&](double n) { predictions.push_back(n); };
  const RefineStats st = refineFace(bt.tri, *cs, ro);
  const double final = static_cast<double>(bt.tri.numTriangles());
  ASSERT_GE(predictions.size(), 5u);
  EXPECT_EQ(predictions.front(), st.predictedTriangles);
  EXPECT_GT(predictions.front(), 0.5 * final);
  EXPECT_LT(predictions.front(), 2.0 * final);
  EXPECT_NEAR(predictions.back(), final, 0.1 * final);
}

TEST(FaceOperators, VisibleWalkStopsAtContours) {
  // A C-shaped domain: from the lower arm the upper arm is behind the slot.
  const Polygon c = {Vec2(0, 0), Vec2(3, 0), Vec2(3, 1), Vec2(1, 1), Vec2(1, 2), Vec2(3, 2), Vec2(3, 3), Vec2(0, 3)};
  const auto cs = isotropicSpace(boxOf(0, 0, 3, 3), 0.25);
  const FaceBoundary b = polygonBoundary({c}, 0.25);
  const FlatBoundary flat = flattenBoundary(b);
  BoundaryTriangulation bt = triangulateBoundary(flat, *cs, 1);
  ASSERT_TRUE(recoverBoundaryEdges(bt.tri, flat, bt.vertexOf, *cs).empty());
  ASSERT_TRUE(removeOutside(bt.tri, flat, bt.vertexOf).empty());
  refineFace(bt.tri, *cs);
  const del2d::Triangulation2d& tri = bt.tri;
  const TriId lower = del2d::locate(tri, Vec2(2.5, 0.5)).tri;
  ASSERT_TRUE(lower.valid());
  const VisibleLocation same = locateVisible(tri, lower, Vec2(2.0, 0.4), 1000);
  EXPECT_TRUE(same.found);
  const VisibleLocation behindSlot = locateVisible(tri, lower, Vec2(2.5, 2.5), 1000);
  EXPECT_FALSE(behindSlot.found);
  const VisibleLocation outside = locateVisible(tri, lower, Vec2(2.5, -1), 1000);
  EXPECT_FALSE(outside.found);
  const VisibleLocation diagonal = locateVisible(tri, lower, Vec2(0.5, 2.5), 1000);
  EXPECT_FALSE(diagonal.found);  // the straight path crosses the slot
  const TriId corner = del2d::locate(tri, Vec2(0.4, 0.4)).tri;
  ASSERT_TRUE(corner.valid());
  const VisibleLocation spine = locateVisible(tri, corner, Vec2(0.45, 2.6), 1000);
  EXPECT_TRUE(spine.found);  // along the spine of the C
}

TEST(FaceOperators, ValidatorCatchesBrokenMeshes) {
  const FaceBoundary b = polygonBoundary({rectangle(0, 0, 1, 1)}, 0);
  FaceMesh m;
  for (const auto& n : b.loops[0]) {
    m.uv.push_back(n.uv);
    m.node.push_back(n.node);
  }
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_TRUE(validateFaceMesh(m, b).empty()) << joined(validateFaceMesh(m, b));
  FaceMesh flipped = m;
  flipped.triangles[1] = {0, 3, 2};
  EXPECT_FALSE(validateFaceMesh(flipped, b).empty());
  FaceMesh missing = m;
  missing.triangles.pop_back();
  EXPECT_FALSE(validateFaceMesh(missing, b).empty());
  FaceMesh overlapping = m;
  overlapping.uv.push_back(Vec2(0.5, 0.5));
  overlapping.node.push_back(-1);
  overlapping.triangles.push_back({0, 1, 4});
  EXPECT_FALSE(validateFaceMesh(overlapping, b).empty());
  FaceMesh wrongNode = m;
  wrongNode.node[2] = 99;
  EXPECT_FALSE(validateFaceMesh(wrongNode, b).empty());
}

}  // namespace
