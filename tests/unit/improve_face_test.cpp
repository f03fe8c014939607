// Tests of improveFaceMesh (thesis alg. 4.2): quality gain on random-point triangulations
// in anisotropic metrics, boundary kept, validity, determinism, per-pass table.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <numbers>

#include "ImproveTestMesh.h"
#include "mesher/core/Error.h"
#include "mesher/surface/improve/FaceQuality.h"
#include "mesher/surface/improve/ImproveFace.h"
#include "mesher/surface/improve/VertexMetricCache.h"

using namespace improve_test;
using aniso::improve::VertexMetricCache;

namespace {

void printQuality(const char* label, const FaceQuality& q) {
  std::printf("  %-22s eta %.4f (sd %.4f, min %.4f)  mu %.4f (sd %.4f)  E_K %.4f\n", label, q.eta.mean(),
              q.eta.stddev(), q.eta.min(), q.mu.mean(), q.mu.stddev(), q.ek.mean());
}

}  // namespace

TEST(ImproveFace, RaisesQualityInAnisotropicMetricAndKeepsBoundary) {
  // Rotated 30°, aspect ratio 5: ~2300 random interior points in the unit square.
  const FunctionCS cs = constantCS(std::numbers::pi / 6, 0.01, 0.05);
  const Mat2 m = transformOf(cs);
  TestFace f = squareFace(m, 7);
  EXPECT_TRI_VALID(f.tri);
  const std::vector<Vec2> before = allPoints(f.tri);
  const auto constrainedBefore = constrainedEdges(f.tri);
  const FaceQuality q0 = faceQuality(f.tri, cs);

  const auto t0 = std::chrono::steady_clock::now();
  const ImproveStats st = improveFaceMesh(f.tri, cs, f.fixed);
  const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const FaceQuality q1 = faceQuality(f.tri, cs);
  std::printf("  %zu triangles, %lld moves, %lld topological + %lld geometric swaps, postprocess %lld flips "
              "%lld moves (bad %lld -> %lld), %.3f ms\n",
              f.tri.numTriangles(), st.moves, st.topologicalSwaps, st.geometricSwaps, st.postprocessFlips,
              st.postprocessMoves, st.badBefore, st.badAfter, 1e3 * sec);
  printQuality("random points", q0);
  printQuality("improved", q1);

  EXPECT_TRI_VALID(f.tri);
  EXPECT_GT(q1.eta.mean(), q0.eta.mean() + 0.08);
  EXPECT_GT(q1.eta.mean(), 0.9);
  EXPECT_GT(q1.eta.min(), q0.eta.min());
  EXPECT_LT(q1.eta.stddev(), q0.eta.stddev());
  EXPECT_LT(q1.mu.stddev(), q0.mu.stddev());
  EXPECT_GT(st.moves, 0);
  // The boundary is kept: fixed vertices bit-identical, the same constrained edges.
  for (std::uint32_t v = 0; v < f.tri.numVertices(); ++v)
    if (f.fixed[v]) {
      EXPECT_EQ(f.tri.point(VertexId(v)), before[v]) << "fixed vertex " << v << " moved";
    }
  EXPECT_EQ(constrainedEdges(f.tri), constrainedBefore);
  EXPECT_EQ(q1.eta.count(), q0.eta.count());
}

TEST(ImproveFace, SurfaceMetricWithParameterizationTensor) {
  // M = M_s M_p with a non-symmetric M_p (a skewed, stretched parameterization).
  Mat2 mp;
  mp << 1.5, 0.4, -0.2, 0.8;
  const FunctionCS cs = constantCS(0.3, 0.012, 0.04, mp);
  const Mat2 m = transformOf(cs);
  TestFace f = squareFace(m, 11);
  const FaceQuality q0 = faceQuality(f.tri, cs);
  improveFaceMesh(f.tri, cs, f.fixed);
  const FaceQuality q1 = faceQuality(f.tri, cs);
  printQuality("skewed M_p, before", q0);
  printQuality("skewed M_p, after", q1);
  EXPECT_TRI_VALID(f.tri);
  EXPECT_GT(q1.eta.mean(), q0.eta.mean() + 0.08);
  EXPECT_GT(q1.eta.min(), q0.eta.min());
}

TEST(ImproveFace, GradedMetricStaysValidAndImproves) {
  // Size growing 6-fold across the square, anisotropy turning with v.
  const FunctionCS cs(box(0, 0, 1, 1), [](const Vec2& p) {
    const double h = 0.01 * (1 + 5 * p.x());
    return SurfaceMetricAt{Metric2d::fromAngle(0.8 * p.y(), h, 2.5 * h), Mat2::Identity()};
  });
  // Points distributed for the graded size: u = F⁻¹(ξ) with density ∝ 1 / h(u)².
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<Vec2> pts;
  for (int k = 0; k < 2200; ++k) {
    const double xi = uni(rng);
    // ∫₀ᵘ (1 + 5s)⁻² ds / ∫₀¹ = ξ  →  u = ξ / (6 − 5ξ)
    pts.emplace_back(xi / (6 - 5 * xi), uni(rng));
  }
  std::vector<Vec2> poly;
  const int n = 40;
  for (int k = 0; k < n; ++k) {
    const double s = double(k) / n, u = s / (6 - 5 * s);  // graded like the interior
    poly.emplace_back(u, 0);
  }
  for (int k = 0; k < 12; ++k) poly.emplace_back(1, double(k) / 12);
  for (int k = 0; k < n; ++k) {
    const double s = 1 - double(k) / n;
    poly.emplace_back(s / (6 - 5 * s), 1);
  }
  for (int k = 0; k < 60; ++k) poly.emplace_back(0, 1 - double(k) / 60);
  TestFace f = buildFace(poly, 1, pts, Mat2::Identity());
  const std::vector<Vec2> before = allPoints(f.tri);
  const FaceQuality q0 = faceQuality(f.tri, cs);
  const ImproveStats st = improveFaceMesh(f.tri, cs, f.fixed);
  const FaceQuality q1 = faceQuality(f.tri, cs);
  printQuality("graded, before", q0);
  printQuality("graded, after", q1);
  EXPECT_TRI_VALID(f.tri);
  EXPECT_GT(q1.eta.mean(), q0.eta.mean() + 0.05);
  EXPECT_GT(st.moves, 0);
  for (std::uint32_t v = 0; v < f.tri.numVertices(); ++v)
    if (f.fixed[v]) {
      EXPECT_EQ(f.tri.point(VertexId(v)), before[v]);
    }
}

TEST(ImproveFace, PassTable) {
  // Thesis Table 4.5: quality after each of N_imp = 0..5 passes (no postprocessing).
  const FunctionCS cs = constantCS(std::numbers::pi / 6, 0.01, 0.05);
  const TestFace start = squareFace(transformOf(cs), 21);
  double previous = 0;
  for (int passes = 0; passes <= 5; ++passes) {
    Triangulation2d tri = start.tri;
    ImproveOptions o;
    o.passes = passes;
    o.postprocess = false;
    improveFaceMesh(tri, cs, start.fixed, o);
    const FaceQuality q = faceQuality(tri, cs);
    char label[32];
    std::snprintf(label, sizeof label, "N_imp = %d", passes);
    printQuality(label, q);
    if (passes <= 2) {
      EXPECT_GT(q.eta.mean(), previous + 0.005) << "pass " << passes;
    }
    EXPECT_TRI_VALID(tri);
    previous = q.eta.mean();
  }
}

TEST(ImproveFace, Deterministic) {
  const FunctionCS cs = constantCS(1.0, 0.01, 0.04);
  const TestFace start = squareFace(transformOf(cs), 5);
  Triangulation2d a = start.tri, b = start.tri;
  const ImproveStats sa = improveFaceMesh(a, cs, start.fixed);
  const ImproveStats sb = improveFaceMesh(b, cs, start.fixed);
  EXPECT_EQ(allPoints(a), allPoints(b));
  EXPECT_EQ(allTriangles(a), allTriangles(b));
  EXPECT_EQ(sa.moves, sb.moves);
  EXPECT_EQ(sa.geometricSwaps, sb.geometricSwaps);
}

TEST(ImproveFace, RejectsBadInput) {
  const FunctionCS cs = constantCS(0, 0.1, 0.1);
  TestFace f = squareFace(transformOf(cs), 1);
  std::vector<std::uint8_t> shortFixed(f.tri.numVertices() - 1, 0);
  EXPECT_THROW(improveFaceMesh(f.tri, cs, shortFixed), MeshingError);
  ImproveOptions o;
  o.passes = -1;
  EXPECT_THROW(improveFaceMesh(f.tri, cs, f.fixed, o), MeshingError);
  // Zero passes and no postprocessing: nothing changes.
  const std::vector<Vec2> before = allPoints(f.tri);
  o.passes = 0;
  o.postprocess = false;
  improveFaceMesh(f.tri, cs, f.fixed, o);
  EXPECT_EQ(allPoints(f.tri), before);
}

TEST(ImproveFace, PoleTrianglesAreLeftAlone) {
  // A sphere-like pole along v = 1: M_p shrinks the u direction to the g_min guard, so the
  // top boundary edges have (almost) no metric length; one 3D point in the surface.
  const FunctionCS cs(box(0, 0, 1, 1), [](const Vec2& p) {
    Mat2 mp = Mat2::Identity();
    mp(0, 0) = std::max(1 - p.y(), 1e-4);
    return SurfaceMetricAt{Metric2d::isotropic(0.04), mp};
  });
  std::vector<Vec2> poly;
  for (int k = 0; k < 25; ++k) poly.emplace_back(k / 25.0, 0);
  for (int k = 0; k < 25; ++k) poly.emplace_back(1, k / 25.0);
  for (int k = 0; k < 6; ++k) poly.emplace_back(1 - k / 6.0, 1);  // the pole: 6 pieces
  for (int k = 0; k < 25; ++k) poly.emplace_back(0, 1 - k / 25.0);
  TestFace f = buildFace(poly, 1, randomPoints(500, 71, 0.01, 0.99), Mat2::Identity());
  // The triangles touching a pole vertex, as sorted vertex triples with coordinates.
  auto poleTriangles = [&](const Triangulation2d& tri) {
    std::vector<std::array<std::uint32_t, 3>> out;
    for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
      const TriId t(k);
      if (!tri.isAlive(t)) continue;
      std::array<std::uint32_t, 3> v{tri.vertex(t, 0).index, tri.vertex(t, 1).index, tri.vertex(t, 2).index};
      bool pole = false;
      for (std::uint32_t x : v) pole = pole || tri.point(VertexId(x)).y() == 1.0;
      std::sort(v.begin(), v.end());
      if (pole) out.push_back(v);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  int poleVertices = 0;
  for (VertexId v : f.boundary) {
    const bool onPole = f.tri.point(v).y() == 1.0;
    EXPECT_EQ(metrics.onDegenerateEdge(v), onPole) << f.tri.point(v).transpose();
    poleVertices += onPole;
  }
  EXPECT_EQ(poleVertices, 7);
  const auto before = poleTriangles(f.tri);
  const std::vector<Vec2> points = allPoints(f.tri);
  const ImproveStats st = improveFaceMesh(f.tri, cs, f.fixed);
  EXPECT_TRI_VALID(f.tri);
  EXPECT_GT(st.moves, 0);
  EXPECT_GT(st.geometricSwaps + st.topologicalSwaps, 0);
  EXPECT_EQ(poleTriangles(f.tri), before);
  for (const auto& t : before)
    for (std::uint32_t v : t) EXPECT_EQ(f.tri.point(VertexId(v)), points[v]);
}
