// Tests of FaceQuality (thesis sec. 2.5: η_M, μ_M, E_K over a face triangulation) and of
// the per-pass vertex metric cache of the improvement.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ImproveTestMesh.h"
#include "mesher/core/Error.h"
#include "mesher/surface/improve/FaceQuality.h"
#include "mesher/surface/improve/VertexMetricCache.h"

using namespace improve_test;
using aniso::improve::symmetricTransform;
using aniso::improve::VertexMetricCache;

namespace {

/// A patch of the equilateral lattice with side L in the metric space of M = M_s M_p,
/// mapped back to (u, v) and triangulated (Delaunay in M); the box triangles removed.
Triangulation2d latticeTriangulation(const Mat2& m, double side, int n) {
  const Mat2 inv = m.inverse();
  std::vector<Vec2> uv;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) uv.push_back(inv * (side * Vec2(i + 0.5 * j, 0.5 * std::sqrt(3.0) * j)));
  Box2 b;
  for (const Vec2& p : uv) b.add(p);
  Triangulation2dOptions o;
  o.transform = m;
  Triangulation2d tri(b, o);
  for (const Vec2& p : uv) EXPECT_EQ(insertPoint(tri, p, m).status, InsertStatus::Inserted);
  std::vector<std::uint8_t> remove(tri.triangleSlots(), 0);
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k)
    if (tri.isAlive(TriId(k)))
      for (int i = 0; i < 3; ++i) remove[k] |= tri.isCorner(tri.vertex(TriId(k), i));
  removeTriangles(tri, remove);
  return tri;
}

std::size_t uniqueEdges(const Triangulation2d& tri) {
  std::size_t halfEdges = 0, border = 0;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k)
    if (tri.isAlive(TriId(k)))
      for (int i = 0; i < 3; ++i) ++halfEdges, border += !tri.neighbour(TriId(k), i).valid();
  return (halfEdges + border) / 2;
}

}  // namespace

TEST(FaceQuality, EquilateralLatticeInMetric) {
  Mat2 mp;
  mp << 1.3, 0.2, -0.4, 0.9;
  const Metric2d ms = Metric2d::fromAngle(0.7, 0.02, 0.08);
  for (const double side : {1.0, 0.5}) {
    for (const Mat2& p : {Mat2(Mat2::Identity()), mp}) {
      const FunctionCS cs(box(-10, -10, 10, 10), [ms, p](const Vec2&) { return SurfaceMetricAt{ms, p}; });
      const Triangulation2d tri = latticeTriangulation(ms.matrix() * p, side, 12);
      EXPECT_TRI_VALID(tri);
      const FaceQuality q = faceQuality(tri, cs);
      EXPECT_EQ(q.eta.count(), tri.numTriangles());
      EXPECT_EQ(q.eta.count(), 2u * 11 * 11);
      EXPECT_EQ(q.mu.count(), uniqueEdges(tri));
      EXPECT_EQ(q.degenerate, 0u);
      EXPECT_NEAR(q.eta.min(), 1.0, 1e-9);
      EXPECT_NEAR(q.eta.max(), 1.0, 1e-9);
      EXPECT_NEAR(q.mu.min(), side, 1e-9 * side);
      EXPECT_NEAR(q.mu.max(), side, 1e-9 * side);
      EXPECT_NEAR(q.mu.stddev(), 0.0, 1e-9);
      // E_K = δ_M(M_s / L, M_s) = √2 |L + 1/L − 2| (MetricComparison.h).
      const double ek = std::sqrt(2.0) * std::abs(side + 1 / side - 2);
      EXPECT_NEAR(q.ek.min(), ek, 1e-7);
      EXPECT_NEAR(q.ek.max(), ek, 1e-7);
    }
  }
}

TEST(FaceQuality, StretchedLatticeIsNotEquilateral) {
  // The same lattice measured in a metric with twice the length along u: η < 1, μ spread.
  const Metric2d ms = Metric2d::fromAngle(0.0, 0.02, 0.02);
  const Triangulation2d tri = latticeTriangulation(ms.matrix(), 1.0, 10);
  const FunctionCS other(box(-10, -10, 10, 10), [](const Vec2&) {
    return SurfaceMetricAt{Metric2d::fromAngle(0.0, 0.01, 0.02), Mat2::Identity()};
  });
  const FaceQuality q = faceQuality(tri, other);
  EXPECT_LT(q.eta.max(), 0.95);
  EXPECT_GT(q.mu.max(), 1.9);
  EXPECT_GT(q.mu.stddev(), 0.1);
  EXPECT_GT(q.ek.mean(), 0.3);
}

TEST(FaceQuality, TriangleListMatchesTriangulation) {
  const FunctionCS cs(box(0, 0, 1, 1), [](const Vec2& p) {
    return SurfaceMetricAt{Metric2d::fromAngle(p.x(), 0.02 * (1 + p.y()), 0.05), Mat2::Identity()};
  });
  const TestFace f = squareFace(Metric2d::fromAngle(0.3, 0.02, 0.05).matrix(), 61);
  std::vector<Vec2> uv = allPoints(f.tri);
  std::vector<std::array<int, 3>> tris;
  for (std::uint32_t k = 0; k < f.tri.triangleSlots(); ++k)
    if (f.tri.isAlive(TriId(k)))
      tris.push_back({int(f.tri.vertex(TriId(k), 0).index), int(f.tri.vertex(TriId(k), 1).index),
                      int(f.tri.vertex(TriId(k), 2).index)});
  const FaceQuality a = faceQuality(f.tri, cs), b = faceQuality(uv, tris, cs);
  EXPECT_EQ(a.eta.count(), b.eta.count());
  EXPECT_EQ(a.mu.count(), b.mu.count());
  EXPECT_EQ(a.ek.count(), b.ek.count());
  EXPECT_NEAR(a.eta.mean(), b.eta.mean(), 1e-12);
  EXPECT_NEAR(a.mu.mean(), b.mu.mean(), 1e-12);
  EXPECT_NEAR(a.ek.mean(), b.ek.mean(), 1e-9);
  EXPECT_DOUBLE_EQ(a.eta.min(), b.eta.min());
  tris.push_back({0, 1, int(uv.size())});
  EXPECT_THROW(faceQuality(uv, tris, cs), MeshingError);
}

TEST(VertexMetricCache, SymmetricTransformKeepsLengths) {
  Mat2 m;
  m << 3.0, -1.2, 0.7, 0.4;
  Mat2 s;
  ASSERT_TRUE(symmetricTransform(m, s));
  EXPECT_DOUBLE_EQ(s(0, 1), s(1, 0));
  std::mt19937_64 rng(2);
  std::normal_distribution<double> g;
  for (int k = 0; k < 20; ++k) {
    const Vec2 x(g(rng), g(rng));
    EXPECT_NEAR((s * x).norm(), (m * x).norm(), 1e-12 * (m * x).norm() + 1e-15);
  }
  EXPECT_FALSE(symmetricTransform(Mat2::Zero(), s));
  Mat2 singular;
  singular << 1, 2, 2, 4;
  EXPECT_FALSE(symmetricTransform(singular, s));
  EXPECT_FALSE(symmetricTransform(Mat2::Constant(std::nan("")), s));
}

TEST(VertexMetricCache, ClassifiesVertices) {
  const FunctionCS cs = constantCS(0, 0.05, 0.05);  // isotropic
  TestFace f = squareFace(transformOf(cs), 62);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  ASSERT_EQ(metrics.size(), f.tri.numVertices());
  int movable = 0;
  for (std::uint32_t v = 0; v < f.tri.numVertices(); ++v) {
    const VertexId id(v);
    EXPECT_EQ(metrics.used(id), f.tri.vertexTriangle(id).valid());
    if (!metrics.used(id)) continue;
    EXPECT_EQ(metrics.gradation(id), 0.0);  // constant metric
    if (f.fixed[v]) {
      EXPECT_FALSE(metrics.movable(id));
    } else {
      EXPECT_TRUE(metrics.movable(id));
      EXPECT_EQ(metrics.idealDegree(id), 6);
      ++movable;
    }
  }
  EXPECT_GT(movable, 100);
  // Border vertices: 4 on a straight side, 3 at a right-angle corner (2 triangles).
  int straight = 0, corners = 0;
  for (VertexId v : f.boundary) {
    const Vec2 p = f.tri.point(v);
    const bool corner = (p.x() == 0 || p.x() == 1) && (p.y() == 0 || p.y() == 1);
    EXPECT_EQ(metrics.idealDegree(v), corner ? 3 : 4);
    corner ? ++corners : ++straight;
  }
  EXPECT_EQ(corners, 4);
  EXPECT_GT(straight, 20);
  // A vertex not flagged fixed but on a constrained edge still does not move.
  std::vector<std::uint8_t> none(f.tri.numVertices(), 0);
  metrics.update(f.tri, cs, none);
  for (VertexId v : f.boundary) EXPECT_FALSE(metrics.movable(v));
  EXPECT_THROW(metrics.update(f.tri, cs, std::vector<std::uint8_t>(3, 0)), MeshingError);
}

TEST(VertexMetricCache, BlendIsOrderIndependentAndExactForEqualMetrics) {
  const FunctionCS cs(box(0, 0, 1, 1), [](const Vec2& p) {
    return SurfaceMetricAt{Metric2d::fromAngle(2 * p.x(), 0.02 * (1 + p.y()), 0.06), Mat2::Identity()};
  });
  TestFace f = squareFace(Metric2d::fromAngle(0, 0.03, 0.06).matrix(), 63);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  const VertexId q[4] = {VertexId(10), VertexId(20), VertexId(30), VertexId(40)};
  const VertexId r[4] = {VertexId(40), VertexId(10), VertexId(30), VertexId(20)};
  EXPECT_EQ(metrics.blend(q, 4), metrics.blend(r, 4));
  const VertexId same[3] = {VertexId(10), VertexId(10), VertexId(10)};
  EXPECT_EQ(metrics.blend(same, 3), metrics.transform(VertexId(10)));
  EXPECT_GT(metrics.gradation(VertexId(10)), 0.0);
}
