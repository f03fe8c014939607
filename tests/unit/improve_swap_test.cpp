// Tests of the edge swaps of the face improvement (thesis sec. 4.6.2–4.6.4): topological
// swap (degree balance, only in low gradation), geometric swap (inner-angles criterion in
// metric space, constrained edges kept), postprocessing of the worst triangles.
#include <gtest/gtest.h>

#include <cstdio>
#include <numbers>

#include "ImproveTestMesh.h"
#include "mesher/core/Error.h"
#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/surface/improve/GeometricSwap.h"
#include "mesher/surface/improve/Postprocess.h"
#include "mesher/surface/improve/TopologicalSwap.h"
#include "mesher/surface/improve/VertexMetricCache.h"

using namespace improve_test;
using namespace aniso::improve;

namespace {

/// Degree (number of edges) per vertex.
std::vector<int> degrees(const Triangulation2d& tri) {
  std::vector<int> d(tri.numVertices(), 0);
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!tri.isAlive(t)) continue;
    for (int i = 0; i < 3; ++i) {
      const TriId u = tri.neighbour(t, i);
      if (u.valid() && u.index < k) continue;
      ++d[tri.vertex(t, kNext[i]).index], ++d[tri.vertex(t, kPrev[i]).index];
    }
  }
  return d;
}

/// Σ (degree − 6)² over the movable (interior) vertices.
long long interiorDegreeDeviation(const Triangulation2d& tri, const VertexMetricCache& metrics) {
  const std::vector<int> d = degrees(tri);
  long long sum = 0;
  for (std::uint32_t v = 0; v < tri.numVertices(); ++v)
    if (metrics.movable(VertexId(v))) sum += (d[v] - 6) * (d[v] - 6);
  return sum;
}

/// Σ (degree − ideal)² over all used vertices.
long long degreeDeviation(const Triangulation2d& tri, const VertexMetricCache& metrics) {
  const std::vector<int> d = degrees(tri);
  long long sum = 0;
  for (std::uint32_t v = 0; v < tri.numVertices(); ++v)
    if (metrics.used(VertexId(v))) {
      const int e = d[v] - metrics.idealDegree(VertexId(v));
      sum += e * e;
    }
  return sum;
}

/// Unconstrained interior edges violating the inner-angles criterion for the constant M.
int innerAngleViolations(const Triangulation2d& tri, const Mat2& m) {
  const PlaneTransform pt(m);
  int bad = 0;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!tri.isAlive(t)) continue;
    for (int i = 0; i < 3; ++i)
      if (!tri.isConstrained(t, i) && tri.neighbour(t, i).valid() && violatesInnerAngles(tri, t, i, pt)) ++bad;
  }
  return bad;
}

}  // namespace

TEST(TopologicalSwap, ReducesTheDegreeDeviation) {
  const FunctionCS cs = constantCS(0.4, 0.01, 0.03);
  TestFace f = squareFace(transformOf(cs), 31);
  const auto constrained = constrainedEdges(f.tri);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  const long long inner0 = interiorDegreeDeviation(f.tri, metrics), all0 = degreeDeviation(f.tri, metrics);
  const TopologicalSwapStats st = topologicalSwap(f.tri, metrics);  // the thesis' rule, no guard
  const long long inner1 = interiorDegreeDeviation(f.tri, metrics), all1 = degreeDeviation(f.tri, metrics);
  std::printf("  sum (deg-6)^2 inside %lld -> %lld, sum (deg-ideal)^2 %lld -> %lld, %lld swaps of %lld edges\n",
              inner0, inner1, all0, all1, st.flipped, st.checked);
  EXPECT_TRI_VALID(f.tri);
  EXPECT_GT(st.flipped, 0);
  EXPECT_LT(inner1, inner0);
  EXPECT_LE(all1, all0 - 2 * st.flipped);  // each swap lowers Σ e² by at least 2
  EXPECT_EQ(constrainedEdges(f.tri), constrained);
}

TEST(TopologicalSwap, GuardKeepsTheNewDiagonalsAcceptable) {
  const FunctionCS cs = constantCS(0.4, 0.01, 0.03);
  const Mat2 m = transformOf(cs);
  TestFace f = squareFace(m, 32);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  GeometricSwapOptions exact;
  geometricSwap(f.tri, metrics, exact);  // metric-Delaunay start
  const long long all0 = degreeDeviation(f.tri, metrics);
  TopologicalSwapOptions o;
  o.angleTolerance = 0.3;
  const TopologicalSwapStats st = topologicalSwap(f.tri, metrics, o);
  EXPECT_GT(st.flipped, 0);
  EXPECT_LT(degreeDeviation(f.tri, metrics), all0);
  // No edge violates the criterion by more than the tolerance, so the geometric swap with
  // that tolerance leaves the topological swaps alone.
  GeometricSwapOptions tolerant;
  tolerant.angleTolerance = 0.3;
  EXPECT_EQ(geometricSwap(f.tri, metrics, tolerant).flipped, 0);
  EXPECT_TRI_VALID(f.tri);
}

TEST(TopologicalSwap, LeavesAreasOfHighGradationAlone) {
  // Anisotropy direction turning fast: every vertex sees a large metric difference.
  const FunctionCS cs(box(0, 0, 1, 1), [](const Vec2& p) {
    return SurfaceMetricAt{Metric2d::fromAngle(60 * p.x() + 40 * p.y(), 0.01, 0.04), Mat2::Identity()};
  });
  TestFace f = squareFace(Metric2d::fromAngle(0, 0.01, 0.04).matrix(), 33);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  for (std::uint32_t v = 0; v < f.tri.numVertices(); ++v)
    if (metrics.used(VertexId(v))) {
      ASSERT_GT(metrics.gradation(VertexId(v)), 0.05);
    }
  EXPECT_EQ(topologicalSwap(f.tri, metrics).flipped, 0);
  // The same mesh in a constant metric does get swaps.
  const FunctionCS constant = constantCS(0, 0.01, 0.04);
  metrics.update(f.tri, constant, f.fixed);
  EXPECT_GT(topologicalSwap(f.tri, metrics).flipped, 0);
  EXPECT_TRI_VALID(f.tri);
}

TEST(GeometricSwap, NoInnerAngleViolationInAConstantAnisotropicMetric) {
  // Euclidean Delaunay triangulation, then swapped in a stretched, rotated metric.
  const FunctionCS cs = constantCS(std::numbers::pi / 5, 0.01, 0.05);
  const Mat2 m = transformOf(cs);
  TestFace f = squareFace(m, 41, Mat2::Identity());
  const auto constrained = constrainedEdges(f.tri);
  const std::vector<Vec2> before = allPoints(f.tri);
  const int violations0 = innerAngleViolations(f.tri, m);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  const GeometricSwapStats st = geometricSwap(f.tri, metrics);
  std::printf("  %d violating edges -> %d, %lld flips in %d sweeps\n", violations0, innerAngleViolations(f.tri, m),
              st.flipped, st.sweeps);
  EXPECT_GT(violations0, 100);
  EXPECT_EQ(innerAngleViolations(f.tri, m), 0);
  EXPECT_FALSE(st.limitReached);
  EXPECT_TRI_VALID(f.tri);
  EXPECT_EQ(constrainedEdges(f.tri), constrained);
  EXPECT_EQ(allPoints(f.tri), before);  // swaps never move a vertex
}

TEST(GeometricSwap, SurfaceTransformationWithParameterizationTensor) {
  // M = M_s M_p not symmetric: the criterion is evaluated on lengths and angles of M x.
  Mat2 mp;
  mp << 0.7, 0.5, -0.3, 1.2;
  const FunctionCS cs = constantCS(1.1, 0.012, 0.05, mp);
  const Mat2 m = transformOf(cs);
  TestFace f = squareFace(m, 42, Mat2::Identity());
  EXPECT_GT(innerAngleViolations(f.tri, m), 100);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  geometricSwap(f.tri, metrics);
  EXPECT_EQ(innerAngleViolations(f.tri, m), 0);
  EXPECT_TRI_VALID(f.tri);
}

TEST(GeometricSwap, ToleranceLeavesOnlySmallViolations) {
  const FunctionCS cs = constantCS(0.9, 0.01, 0.05);
  const Mat2 m = transformOf(cs);
  TestFace f = squareFace(m, 43, Mat2::Identity());
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  GeometricSwapOptions o;
  o.angleTolerance = 0.3;
  geometricSwap(f.tri, metrics, o);
  double worst = 0;
  for (std::uint32_t k = 0; k < f.tri.triangleSlots(); ++k) {
    const TriId t(k);
    if (!f.tri.isAlive(t)) continue;
    for (int i = 0; i < 3; ++i) {
      const TriId u = f.tri.neighbour(t, i);
      if (!u.valid() || f.tri.isConstrained(t, i)) continue;
      const VertexId d = f.tri.vertex(u, f.tri.neighbourIndex(u, t));
      worst = std::max(worst, oppositeAngleSum(m, f.tri.point(f.tri.vertex(t, i)), f.tri.point(f.tri.vertex(t, kNext[i])),
                                               f.tri.point(f.tri.vertex(t, kPrev[i])), f.tri.point(d)));
    }
  }
  EXPECT_LE(worst, std::numbers::pi + 0.3 + 1e-9);
  EXPECT_GT(innerAngleViolations(f.tri, m), 0);  // small violations stay
  EXPECT_TRI_VALID(f.tri);
}

TEST(GeometricSwap, VariableMetricTerminatesValid) {
  // Metric per quadrilateral (blend of its vertices): a rotating, graded field.
  const FunctionCS cs(box(0, 0, 1, 1), [](const Vec2& p) {
    const double h = 0.01 * (1 + 2 * p.y());
    return SurfaceMetricAt{Metric2d::fromAngle(3 * p.x(), h, 4 * h), Mat2::Identity()};
  });
  TestFace f = squareFace(Metric2d::fromAngle(0, 0.012, 0.04).matrix(), 44, Mat2::Identity());
  const auto constrained = constrainedEdges(f.tri);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  const GeometricSwapStats st = geometricSwap(f.tri, metrics);
  EXPECT_GT(st.flipped, 0);
  EXPECT_FALSE(st.limitReached);
  EXPECT_TRI_VALID(f.tri);
  EXPECT_EQ(constrainedEdges(f.tri), constrained);
  // Every edge satisfies the criterion in its own quadrilateral's metric.
  for (std::uint32_t k = 0; k < f.tri.triangleSlots(); ++k)
    for (int i = 0; i < 3; ++i)
      if (f.tri.isAlive(TriId(k))) {
        EXPECT_FALSE(violatesSwapCriterion(f.tri, metrics, TriId(k), i, 0));
      }
}

TEST(Postprocess, ImprovesTheWorstTriangles) {
  const FunctionCS cs = constantCS(0.2, 0.01, 0.04);
  const Mat2 m = transformOf(cs);
  TestFace f = squareFace(m, 51);
  const std::vector<Vec2> before = allPoints(f.tri);
  const auto constrained = constrainedEdges(f.tri);
  const EtaSummary q0 = etaSummary(f.tri, m);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  const PostprocessStats st = postprocess(f.tri, metrics);
  const EtaSummary q1 = etaSummary(f.tri, m);
  std::printf("  bad (eta < 0.6) %lld -> %lld, %lld flips, %lld moves; min %.4f -> %.4f, mean %.4f -> %.4f\n",
              st.badBefore, st.badAfter, st.flips, st.moves, q0.min, q1.min, q0.mean, q1.mean);
  EXPECT_TRI_VALID(f.tri);
  EXPECT_LT(st.badAfter, st.badBefore / 2);
  EXPECT_GT(q1.min, q0.min);
  EXPECT_GT(q1.mean, q0.mean);
  EXPECT_EQ(countBadTriangles(f.tri, metrics, 0.6), st.badAfter);
  EXPECT_EQ(constrainedEdges(f.tri), constrained);
  for (std::uint32_t v = 0; v < f.tri.numVertices(); ++v)
    if (f.fixed[v]) {
      EXPECT_EQ(f.tri.point(VertexId(v)), before[v]);
    }
}
