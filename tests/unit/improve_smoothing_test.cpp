// Tests of the mixed metric Laplace smoothing (thesis sec. 4.6.1): quality gain, validity
// (exact orientation) including a concave domain, fixed vertices untouched, the metric
// version (eq. 4.3) in a graded field, unusable metrics, determinism and throughput.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <limits>
#include <numbers>

#include "ImproveTestMesh.h"
#include "mesher/core/Error.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/surface/improve/FaceQuality.h"
#include "mesher/surface/improve/GeometricSwap.h"
#include "mesher/surface/improve/LaplaceSmoothing.h"
#include "mesher/surface/improve/VertexMetricCache.h"

using namespace improve_test;
using aniso::improve::gatherRing;
using aniso::improve::laplaceSmoothing;
using aniso::improve::SmoothingOptions;
using aniso::improve::SmoothingStats;
using aniso::improve::VertexMetricCache;

namespace {

void expectFixedUnmoved(const TestFace& f, const std::vector<Vec2>& before) {
  for (std::uint32_t v = 0; v < f.tri.numVertices(); ++v)
    if (f.fixed[v]) {
      EXPECT_EQ(f.tri.point(VertexId(v)), before[v]) << "fixed vertex " << v << " moved";
    }
}

/// Isotropic size growing 10-fold in u, and the matching point distribution.
FunctionCS gradedCS() {
  return FunctionCS(box(0, 0, 1, 1), [](const Vec2& p) {
    return SurfaceMetricAt{Metric2d::isotropic(0.01 * (1 + 9 * p.x())), Mat2::Identity()};
  });
}
/// u with density ∝ (1 + 9u)⁻²: u = ξ / (10 − 9ξ).
double gradedU(double xi) { return xi / (10 - 9 * xi); }

TestFace gradedFace(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<Vec2> pts;
  for (int k = 0; k < 1600; ++k) pts.emplace_back(gradedU(uni(rng)), uni(rng));
  std::vector<Vec2> poly;
  const int n = 45, right = 10, left = 100;
  for (int k = 0; k < n; ++k) poly.emplace_back(gradedU(double(k) / n), 0);
  for (int k = 0; k < right; ++k) poly.emplace_back(1, double(k) / right);
  for (int k = 0; k < n; ++k) poly.emplace_back(gradedU(1 - double(k) / n), 1);
  for (int k = 0; k < left; ++k) poly.emplace_back(0, 1 - double(k) / left);
  return buildFace(poly, 1, pts, Mat2::Identity());
}

}  // namespace

TEST(LaplaceSmoothing, RaisesMeanQualityKeepsValidityAndFixedVertices) {
  const FunctionCS cs = constantCS(0.5, 0.01, 0.04);
  const Mat2 m = transformOf(cs);
  TestFace f = squareFace(m, 3);
  const std::vector<Vec2> before = allPoints(f.tri);
  const EtaSummary q0 = etaSummary(f.tri, m);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  SmoothingOptions o;
  o.iterations = 3;
  const SmoothingStats st = laplaceSmoothing(f.tri, metrics, o);
  const EtaSummary q1 = etaSummary(f.tri, m);
  std::printf("  eta mean %.4f -> %.4f, min %.4f -> %.4f; %lld moves (%lld halved, %lld refused) of %lld visits\n",
              q0.mean, q1.mean, q0.min, q1.min, st.moved, st.halved, st.rejected, st.visited);
  EXPECT_TRI_VALID(f.tri);
  EXPECT_GT(q1.mean, q0.mean + 0.1);
  EXPECT_GE(q1.min, q0.min);  // a star below the floor (0.5) only ever gets a better worst element
  EXPECT_GT(st.moved, 0);
  EXPECT_EQ(st.metricVersion, 0);  // constant metric: eq. 4.2 everywhere
  expectFixedUnmoved(f, before);
  EXPECT_EQ(constrainedEdges(f.tri).size(), f.boundary.size());
}

TEST(LaplaceSmoothing, StrictGuardNeverLowersTheWorstElementOfAStar) {
  const FunctionCS cs = constantCS(-0.7, 0.02, 0.05);
  const Mat2 m = transformOf(cs);
  TestFace f = squareFace(m, 4);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  // With floor 1 every accepted move raises its star's worst element, so in a constant
  // metric the worst element of the mesh never gets worse, sweep after sweep.
  const EtaSummary q0 = etaSummary(f.tri, m);
  SmoothingOptions o;
  o.iterations = 1;
  o.qualityFloor = 1;
  double previousMin = q0.min;
  for (int sweep = 0; sweep < 4; ++sweep) {
    laplaceSmoothing(f.tri, metrics, o);
    const double worst = etaSummary(f.tri, m).min;
    EXPECT_GE(worst, previousMin) << "sweep " << sweep;
    previousMin = worst;
  }
  const EtaSummary q1 = etaSummary(f.tri, m);
  EXPECT_TRI_VALID(f.tri);
  EXPECT_GT(q1.mean, q0.mean + 0.05);
}

TEST(LaplaceSmoothing, ConcaveDomainNeverInverts) {
  // L-shaped face with a strongly anisotropic metric across the reflex corner.
  const FunctionCS cs = constantCS(0.25, 0.01, 0.08);
  const Mat2 m = transformOf(cs);
  const std::vector<Vec2> poly = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 0.45), Vec2(0.45, 0.45), Vec2(0.45, 1), Vec2(0, 1)};
  std::vector<Vec2> pts;
  for (const Vec2& p : randomPoints(3000, 9))
    if (!(p.x() > 0.45 && p.y() > 0.45)) pts.push_back(p);
  TestFace f = buildFace(poly, 40, pts, m);
  EXPECT_TRI_VALID(f.tri);
  // The plain Laplace target inverts the star of some vertices here (why the check exists).
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  int inverting = 0;
  std::vector<VertexId> ring;
  for (std::uint32_t v = 0; v < f.tri.numVertices(); ++v) {
    if (!metrics.movable(VertexId(v)) || !gatherRing(f.tri, VertexId(v), ring)) continue;
    Vec2 target = Vec2::Zero();
    for (VertexId w : ring) target += f.tri.point(w);
    target /= static_cast<double>(ring.size());
    for (std::size_t k = 0; k < ring.size(); ++k)
      if (!(predicates::orient2d(target.data(), f.tri.coords(ring[k]), f.tri.coords(ring[(k + 1) % ring.size()])) > 0)) {
        ++inverting;
        break;
      }
  }
  std::printf("  %d vertices whose unchecked Laplace move would invert a triangle\n", inverting);
  EXPECT_GT(inverting, 0);
  const std::vector<Vec2> before = allPoints(f.tri);
  SmoothingOptions o;
  o.iterations = 5;
  o.qualityFloor = -std::numeric_limits<double>::infinity();  // orientation check only (thesis)
  const SmoothingStats st = laplaceSmoothing(f.tri, metrics, o);
  EXPECT_TRI_VALID(f.tri);
  EXPECT_GT(st.rejected + st.halved, 0);
  expectFixedUnmoved(f, before);
}

TEST(LaplaceSmoothing, MetricVersionFollowsARotatingAnisotropy) {
  // Aspect ratio 4 with the main direction turning by 6 rad across the face: the mixed
  // smoothing uses eq. 4.3 (mid-edge metrics) and beats the plain average clearly.
  const double rot = 6;
  const FunctionCS cs(box(0, 0, 1, 1), [rot](const Vec2& p) {
    return SurfaceMetricAt{Metric2d::fromAngle(rot * p.x(), 0.01, 0.04), Mat2::Identity()};
  });
  std::vector<Vec2> poly;  // boundary nodes one metric unit apart
  auto side = [&](const Vec2& a, const Vec2& b) {
    const double last = 1 - 0.3 / (cs.getMetric(b).transformation() * (b - a)).norm();
    for (double t = 0; t < last; t += 1 / (cs.getMetric(a + t * (b - a)).transformation() * (b - a)).norm())
      poly.push_back(a + t * (b - a));
  };
  side(Vec2(0, 0), Vec2(1, 0)), side(Vec2(1, 0), Vec2(1, 1)), side(Vec2(1, 1), Vec2(0, 1)), side(Vec2(0, 1), Vec2(0, 0));
  TestFace start = buildFace(poly, 1, randomPoints(static_cast<int>(1 / (0.01 * 0.04) / 0.866), 3), Mat2::Identity());
  VertexMetricCache metrics;
  metrics.update(start.tri, cs, start.fixed);
  aniso::improve::geometricSwap(start.tri, metrics);  // metric-Delaunay start
  FaceQuality q[2];
  long long metricTargets[2] = {0, 0};
  for (int version = 0; version < 2; ++version) {
    Triangulation2d tri = start.tri;
    SmoothingOptions o;
    o.iterations = 1;
    o.lowGradation = version == 0 ? std::numeric_limits<double>::infinity() : 0.05;  // plain, mixed
    for (int sweep = 0; sweep < 4; ++sweep) {
      metrics.update(tri, cs, start.fixed);
      metricTargets[version] += laplaceSmoothing(tri, metrics, o).metricVersion;
    }
    EXPECT_TRI_VALID(tri);
    q[version] = faceQuality(tri, cs);
  }
  std::printf("  eq. 4.2 only  eta %.4f (sd %.4f)  mu sd %.4f  E_K %.4f\n", q[0].eta.mean(), q[0].eta.stddev(),
              q[0].mu.stddev(), q[0].ek.mean());
  std::printf("  mixed 4.2/4.3 eta %.4f (sd %.4f)  mu sd %.4f  E_K %.4f  (%lld metric targets)\n", q[1].eta.mean(),
              q[1].eta.stddev(), q[1].mu.stddev(), q[1].ek.mean(), metricTargets[1]);
  EXPECT_EQ(metricTargets[0], 0);
  EXPECT_GT(metricTargets[1], 0);
  EXPECT_GT(q[1].eta.mean(), q[0].eta.mean() + 0.005);
  EXPECT_LT(q[1].ek.mean(), q[0].ek.mean());
  EXPECT_LT(q[1].mu.stddev(), q[0].mu.stddev());
}

TEST(LaplaceSmoothing, SizeNormalisedMetricVersionDoesNotOverGrade) {
  // Size ×10 across the face, vertex density following it: the connectivity already
  // carries the gradation. Verbatim eq. 4.3 drags the vertices towards the fine side; the
  // size-normalised form (default) equals the plain average for an isotropic metric.
  const FunctionCS cs = gradedCS();
  const TestFace start = gradedFace(5);
  double meanShift[3] = {0, 0, 0};
  FaceQuality q[3];
  for (int version = 0; version < 3; ++version) {  // plain, normalised 4.3, verbatim 4.3
    Triangulation2d tri = start.tri;
    VertexMetricCache metrics;
    SmoothingOptions o;
    o.iterations = 1;
    o.lowGradation = version == 0 ? std::numeric_limits<double>::infinity() : -1;
    o.metricSize = version == 2;
    for (int sweep = 0; sweep < 12; ++sweep) {
      metrics.update(tri, cs, start.fixed);
      laplaceSmoothing(tri, metrics, o);
    }
    EXPECT_TRI_VALID(tri);
    q[version] = faceQuality(tri, cs);
    int n = 0;
    for (std::uint32_t v = 0; v < tri.numVertices(); ++v)
      if (metrics.movable(VertexId(v))) meanShift[version] += tri.point(VertexId(v)).x() - start.tri.point(VertexId(v)).x(), ++n;
    meanShift[version] /= n;
  }
  const char* names[3] = {"eq. 4.2", "eq. 4.3 normalised", "eq. 4.3 verbatim"};
  for (int k = 0; k < 3; ++k)
    std::printf("  %-18s eta %.4f  mu sd %.4f  E_K %.4f  mean u shift %+.5f\n", names[k], q[k].eta.mean(),
                q[k].mu.stddev(), q[k].ek.mean(), meanShift[k]);
  EXPECT_NEAR(q[1].eta.mean(), q[0].eta.mean(), 1e-6);
  EXPECT_NEAR(meanShift[1], meanShift[0], 1e-6);
  EXPECT_LT(meanShift[2], meanShift[0] - 0.001);  // towards the fine side (small u)
  EXPECT_GT(q[2].ek.mean(), q[1].ek.mean());
}

TEST(LaplaceSmoothing, UnusableMetricHoldsTheVertex) {
  // The control space fails (NaN) in a disc: those vertices stay, the rest is smoothed.
  const Metric2d good = Metric2d::fromAngle(0.3, 0.015, 0.04);
  const FunctionCS cs(box(0, 0, 1, 1), [good](const Vec2& p) {
    SurfaceMetricAt s{good, Mat2::Identity()};
    if ((p - Vec2(0.5, 0.5)).norm() < 0.15) s.parameterization = Mat2::Constant(std::nan(""));
    return s;
  });
  TestFace f = squareFace(good.matrix(), 12);
  const std::vector<Vec2> before = allPoints(f.tri);
  VertexMetricCache metrics;
  metrics.update(f.tri, cs, f.fixed);
  int unusable = 0;
  for (std::uint32_t v = 0; v < f.tri.numVertices(); ++v)
    if (metrics.unusableMetric(VertexId(v))) {
      ++unusable;
      EXPECT_FALSE(metrics.movable(VertexId(v)));
      EXPECT_TRUE(metrics.transform(VertexId(v)).allFinite());
    }
  EXPECT_GT(unusable, 10);
  laplaceSmoothing(f.tri, metrics);
  EXPECT_TRI_VALID(f.tri);
  for (std::uint32_t v = 0; v < f.tri.numVertices(); ++v)
    if (metrics.unusableMetric(VertexId(v))) {
      EXPECT_EQ(f.tri.point(VertexId(v)), before[v]);
    }
}

TEST(LaplaceSmoothing, DeterministicAndFast) {
  // ~100k vertices, isotropic metric.
  const FunctionCS cs = constantCS(0, 0.0033, 0.0033);
  const TestFace start = squareFace(transformOf(cs), 17);
  Triangulation2d a = start.tri, b = start.tri;
  VertexMetricCache ma, mb;
  const auto t0 = std::chrono::steady_clock::now();
  ma.update(a, cs, start.fixed);
  const auto t1 = std::chrono::steady_clock::now();
  SmoothingOptions o;
  o.iterations = 2;
  const SmoothingStats sa = laplaceSmoothing(a, ma, o);
  const auto t2 = std::chrono::steady_clock::now();
  mb.update(b, cs, start.fixed);
  const SmoothingStats sb = laplaceSmoothing(b, mb, o);
  const double cacheSec = std::chrono::duration<double>(t1 - t0).count();
  const double smoothSec = std::chrono::duration<double>(t2 - t1).count();
  std::printf("  %zu vertices: metric cache %.1f ms (%.2e vertices/s), smoothing %lld visits in %.1f ms (%.2e vertices/s)\n",
              a.numVertices(), 1e3 * cacheSec, a.numVertices() / cacheSec, sa.visited, 1e3 * smoothSec,
              sa.visited / smoothSec);
  EXPECT_EQ(allPoints(a), allPoints(b));
  EXPECT_EQ(sa.moved, sb.moved);
  EXPECT_GT(a.numVertices(), 80000u);
  EXPECT_TRI_VALID(a);
}
