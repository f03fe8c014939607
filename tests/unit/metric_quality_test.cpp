// Tests of the quality measures in metric space (sec. 2.5): mean ratio η_M (2.47–2.48),
// metric edge length μ_M (2.49), non-conformity E_K (2.50–2.51), and the accumulator.
#include <gtest/gtest.h>

#include <cmath>

#include "mesher/core/Error.h"
#include "mesher/metric/MeanRatio.h"
#include "mesher/metric/MetricLength.h"
#include "mesher/metric/NonConformity.h"
#include "mesher/metric/QualityStats.h"
#include "mesher/metric/SurfaceMetric.h"

using namespace aniso;

namespace {
const double kS3 = std::sqrt(3.0);
}

TEST(MetricQuality, MeanRatioOfReferenceShapes) {
  const Vec2 a(0, 0), b(1, 0), c(0.5, kS3 / 2);
  EXPECT_NEAR(meanRatio(a, b, c), 1.0, 1e-15);
  EXPECT_NEAR(meanRatio(Vec2(3 * a), Vec2(3 * b), Vec2(3 * c)), 1.0, 1e-15);  // scale-free
  EXPECT_NEAR(meanRatio(a, c, b), -1.0, 1e-15);  // inverted (clockwise)
  // Right isosceles: 4√3 · ½ / (1 + 1 + 2) = √3/2.
  EXPECT_NEAR(meanRatio(Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)), kS3 / 2, 1e-15);
  // Degenerate: collinear and coincident points give 0, never NaN.
  EXPECT_EQ(meanRatio(Vec2(0, 0), Vec2(1, 1), Vec2(2, 2)), 0.0);
  EXPECT_EQ(meanRatio(Vec2(1, 1), Vec2(1, 1), Vec2(1, 1)), 0.0);

  const Vec3 p1(0, 0, 0), p2(1, 0, 0), p3(0.5, kS3 / 2, 0), p4(0.5, kS3 / 6, std::sqrt(2.0 / 3));
  EXPECT_NEAR(meanRatio(p1, p2, p3, p4), 1.0, 1e-14);
  EXPECT_NEAR(meanRatio(p1, p3, p2, p4), -1.0, 1e-14);
  EXPECT_EQ(meanRatio(p1, p2, p3, Vec3(0.2, 0.3, 0)), 0.0);  // flat
  EXPECT_EQ(meanRatio(p1, p1, p1, p1), 0.0);
  // Corner tetrahedron (0, e1, e2, e3): V = 1/6, Σl² = 3 + 3·2 = 9: 12 ∛(9/36) / 9.
  EXPECT_NEAR(meanRatio(p1, Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)), 12 * std::cbrt(0.25) / 9, 1e-14);
}

TEST(MetricQuality, MeanRatioInMetricSpace) {
  // A triangle that is equilateral in metric space (M⁻¹ applied to an equilateral one) is
  // stretched in the plane: η < 1 but η_M = 1.
  const Metric2d m = Metric2d::fromAngle(0.5, 0.05, 1.0);
  const Mat2 inv = m.inverseMatrix();
  const Vec2 a = inv * Vec2(0, 0), b = inv * Vec2(1, 0), c = inv * Vec2(0.5, kS3 / 2);
  EXPECT_LT(meanRatio(a, b, c), 0.5);
  EXPECT_NEAR(meanRatio(m, a, b, c), 1.0, 1e-12);
  // The same with a surface transformation M = M_s M_p.
  Mat2 mp;
  mp << 1.2, 0.3, 0.3, 0.7;
  const Mat2 full = surfaceTransformation(m, mp);
  const Mat2 fullInv = full.inverse();
  const Vec2 u = fullInv * Vec2(0, 0), v = fullInv * Vec2(1, 0), w = fullInv * Vec2(0.5, kS3 / 2);
  EXPECT_NEAR(meanRatio(full, u, v, w), 1.0, 1e-12);
  // 3D: a metric-equilateral tetrahedron.
  const Metric3d m3 = Metric3d::fromDirections(Vec3(1, 1, 0), Vec3(-1, 1, 0), Vec3(0, 0, 1), 0.1, 1.0, 3.0);
  const Mat3 i3 = m3.inverseMatrix();
  const Vec3 p1 = i3 * Vec3(0, 0, 0), p2 = i3 * Vec3(1, 0, 0), p3 = i3 * Vec3(0.5, kS3 / 2, 0),
             p4 = i3 * Vec3(0.5, kS3 / 6, std::sqrt(2.0 / 3));
  EXPECT_NEAR(meanRatio(m3, p1, p2, p3, p4), 1.0, 1e-12);
  EXPECT_LT(meanRatio(p1, p2, p3, p4), 0.5);
}

TEST(MetricQuality, MetricEdgeLength) {
  // A unit edge in the identity metric, and an edge of length h_i along e_i, measure 1.
  EXPECT_NEAR(metricLength(Metric2d(), Vec2(0, 0), Vec2(0.6, 0.8)), 1.0, 1e-15);
  EXPECT_NEAR(metricLength(Metric3d(), Vec3(1, 2, 3), Vec3(1, 2, 4)), 1.0, 1e-15);
  const Metric2d m = Metric2d::fromAngle(M_PI / 3, 0.2, 0.9);
  const Vec2 e1(std::cos(M_PI / 3), std::sin(M_PI / 3)), e2(-e1.y(), e1.x());
  EXPECT_NEAR(metricLength(m, Vec2(1, 1), Vec2(Vec2(1, 1) + 0.2 * e1)), 1.0, 1e-14);
  EXPECT_NEAR(metricLength(m, Vec2(1, 1), Vec2(Vec2(1, 1) + 0.9 * e2)), 1.0, 1e-14);
  EXPECT_NEAR(metricLength(m, Vec2(1, 1), Vec2(Vec2(1, 1) + 0.4 * e1)), 2.0, 1e-14);
}

TEST(MetricQuality, NonConformity) {
  // A unit equilateral triangle of the prescribed metric conforms: E_K = 0.
  const Metric2d m = Metric2d::fromAngle(-0.3, 0.1, 0.4);
  const Mat2 inv = m.inverseMatrix();
  const Vec2 a = inv * Vec2(0, 0), b = inv * Vec2(1, 0), c = inv * Vec2(0.5, kS3 / 2);
  EXPECT_NEAR(nonConformity(m, a, b, c), 0.0, 1e-12);
  // Rotated in metric space: still a unit element.
  const Vec2 r1 = inv * Vec2(0.2, 0.1), r2 = inv * Vec2(0.2 + std::cos(1.0), 0.1 + std::sin(1.0)),
             r3 = inv * Vec2(0.2 + std::cos(1.0 + M_PI / 3), 0.1 + std::sin(1.0 + M_PI / 3));
  EXPECT_NEAR(nonConformity(m, r1, r2, r3), 0.0, 1e-11);
  // Twice too big: M_K = M/2, E_K = δ_M(M/2, M) = √2 |½ + 2 − 2|.
  EXPECT_NEAR(nonConformity(m, Vec2(2 * a), Vec2(2 * b), Vec2(2 * c)), std::sqrt(2.0) * 0.5, 1e-12);
  // Surface: a parametric triangle that is unit-equilateral for M = M_s M_p.
  Mat2 mp;
  mp << 2.0, -0.4, -0.4, 0.5;
  const Mat2 full = surfaceTransformation(m, mp).inverse();
  const Vec2 u = full * Vec2(0, 0), v = full * Vec2(1, 0), w = full * Vec2(0.5, kS3 / 2);
  EXPECT_NEAR(nonConformitySurface(m, mp, u, v, w), 0.0, 1e-11);
  EXPECT_GT(nonConformity(m, u, v, w), 0.1);  // without M_p it does not conform
  // 3D.
  const Metric3d m3 = Metric3d::isotropic(0.5);
  const Vec3 p1(0, 0, 0), p2(0.5, 0, 0), p3(0.25, 0.5 * kS3 / 2, 0), p4(0.25, 0.5 * kS3 / 6, 0.5 * std::sqrt(2.0 / 3));
  EXPECT_NEAR(nonConformity(m3, p1, p2, p3, p4), 0.0, 1e-12);
  EXPECT_THROW(nonConformity(m, a, a, c), MeshingError);
}

TEST(MetricQuality, StatsAccumulator) {
  QualityStats s;
  EXPECT_EQ(s.count(), 0u);
  EXPECT_EQ(s.mean(), 0.0);
  EXPECT_EQ(s.stddev(), 0.0);
  for (double v : {1.0, 2.0, 3.0, 4.0, 5.0}) s.add(v);
  EXPECT_EQ(s.count(), 5u);
  EXPECT_NEAR(s.mean(), 3.0, 1e-15);
  EXPECT_NEAR(s.stddev(), std::sqrt(2.0), 1e-15);  // population standard deviation
  EXPECT_EQ(s.min(), 1.0);
  EXPECT_EQ(s.max(), 5.0);
  // Merging two halves equals one pass.
  QualityStats a, b, all;
  for (int i = 0; i < 100; ++i) {
    const double v = std::sin(i * 0.37) * 3 + 10;
    (i < 37 ? a : b).add(v);
    all.add(v);
  }
  a.merge(b);
  EXPECT_EQ(a.count(), all.count());
  EXPECT_NEAR(a.mean(), all.mean(), 1e-12);
  EXPECT_NEAR(a.stddev(), all.stddev(), 1e-12);
  EXPECT_EQ(a.min(), all.min());
  EXPECT_EQ(a.max(), all.max());
  QualityStats empty;
  empty.merge(all);
  EXPECT_NEAR(empty.mean(), all.mean(), 1e-15);
  EXPECT_THROW(s.add(std::nan("")), MeshingError);
  EXPECT_THROW(s.add(INFINITY), MeshingError);
}
