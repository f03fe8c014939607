// Tests of the metric operations of sec. 2.3 and the anisotropy limit (eq. 2.42):
// interpolation (2.18), intersection (2.20–2.23), comparison (2.24–2.25).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <random>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/metric/AnisotropyLimit.h"
#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricInterpolation.h"
#include "mesher/metric/MetricIntersection.h"

using namespace aniso;

namespace {

Metric2d randomMetric2d(std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), logh(-2, 1);
  return Metric2d::fromAngle(angle(rng), std::pow(10, logh(rng)), std::pow(10, logh(rng)));
}

Metric3d randomMetric3d(std::mt19937& rng) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> logh(-2, 1);
  const Mat3 r = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
  return Metric3d::fromDirections(r.col(0), r.col(1), r.col(2), std::pow(10, logh(rng)),
                                  std::pow(10, logh(rng)), std::pow(10, logh(rng)));
}

std::vector<Vec2> circleDirections(int n) {
  std::vector<Vec2> d;
  for (int i = 0; i < n; ++i) d.emplace_back(std::cos(M_PI * i / n), std::sin(M_PI * i / n));
  return d;
}

/// Fibonacci points on the unit sphere (a half would do: the ratios are even).
std::vector<Vec3> sphereDirections(int n) {
  std::vector<Vec3> d;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z);
    d.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return d;
}

/// min over sampled directions of |R u| / |A u|: ≥ 1 means the unit ball of R lies inside
/// the unit ball of A (containment), = 1 means they touch.
template <int D, class Dirs>
double minRatio(const Metric<D>& r, const Metric<D>& a, const Dirs& dirs) {
  double best = INFINITY;
  for (const auto& u : dirs) best = std::min(best, r.length(u) / a.length(u));
  return best;
}

/// Largest length, measured in metric a, of a vector of unit length in metric r:
/// the spectral norm ‖A R⁻¹‖₂ (exact, by SVD). The unit ball of r lies inside the unit
/// ball of a iff this is ≤ 1, and touches its boundary iff it equals 1.
template <int D>
double spectralRatio(const Metric<D>& r, const Metric<D>& a) {
  const Eigen::Matrix<double, D, D> x = a.matrix() * r.matrix().inverse();
  return Eigen::JacobiSVD<Eigen::Matrix<double, D, D>>(x).singularValues()(0);
}

/// Sampled version: max over unit vectors w of metric space of r of |A R⁻¹ w|.
template <int D, class Dirs>
double sampledRatio(const Metric<D>& r, const Metric<D>& a, const Dirs& dirs) {
  double worst = 0;
  for (const auto& w : dirs) worst = std::max(worst, a.length(r.matrix().inverse() * w));
  return worst;
}

/// Touching, exactly: the unit ball of r touches the one of a input unless the other
/// input lies strictly inside it — then r is that other input. When neither input
/// contains the other ("crossing" ellipses, decided independently from a and b alone),
/// r touches both. Counts the crossing pairs.
template <int D>
void checkTouching(const Metric<D>& r, const Metric<D>& a, const Metric<D>& b, int& crossing) {
  const double ta = spectralRatio(r, a), tb = spectralRatio(r, b);
  EXPECT_NEAR(std::max(ta, tb), 1.0, 1e-9);
  const bool aInsideB = spectralRatio(a, b) <= 1 + 1e-12, bInsideA = spectralRatio(b, a) <= 1 + 1e-12;
  if (!aInsideB && !bInsideA) {
    ++crossing;
    EXPECT_NEAR(ta, 1.0, 1e-9);
    EXPECT_NEAR(tb, 1.0, 1e-9);
  } else {
    const Metric<D>& inner = aInsideB ? a : b;
    EXPECT_LT((r.matrix() - inner.matrix()).norm(), 1e-9 * inner.matrix().norm());
  }
}

}  // namespace

// ---- interpolation ----

TEST(MetricInterpolation, EqualMetricsGiveThatMetric) {
  for (double t : {0.0, 0.25, 0.5, 1.0}) {
    EXPECT_LT((interpolate(Metric2d(), Metric2d(), t).matrix() - Mat2::Identity()).norm(), 1e-15);
    EXPECT_LT((interpolate(Metric3d(), Metric3d(), t).matrix() - Mat3::Identity()).norm(), 1e-15);
  }
  std::mt19937 rng(3);
  for (int k = 0; k < 20; ++k) {
    const Metric2d m = randomMetric2d(rng);
    EXPECT_LT((interpolate(m, m, 0.37).matrix() - m.matrix()).norm(), 1e-12 * m.matrix().norm());
    const Metric3d m3 = randomMetric3d(rng);
    EXPECT_LT((interpolate(m3, m3, 0.61).matrix() - m3.matrix()).norm(), 1e-11 * m3.matrix().norm());
  }
}

TEST(MetricInterpolation, IsotropicLengthsInterpolateLinearly) {
  // M⁻¹ = h I: eq. 2.18 interpolates the length linearly.
  const Metric2d a = Metric2d::isotropic(0.1), b = Metric2d::isotropic(0.5);
  for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
    const Metric2d m = interpolate(a, b, t);
    EXPECT_NEAR(m.lengthAlong(Vec2(1, 0)), 0.1 + t * 0.4, 1e-14);
    EXPECT_NEAR(m.lengthAlong(Vec2(1, 1)), 0.1 + t * 0.4, 1e-14);
  }
  // Endpoints exact.
  const Metric2d c = Metric2d::fromAngle(0.3, 0.2, 1.0);
  EXPECT_EQ(interpolate(c, b, 0.0).matrix(), c.matrix());
  EXPECT_EQ(interpolate(c, b, 1.0).matrix(), b.matrix());
}

TEST(MetricInterpolation, AnisotropicEqualAxesInterpolateLengths) {
  // Same directions: the lengths along each axis are interpolated linearly.
  const Metric2d a = Metric2d::fromAngle(0.4, 0.1, 1.0), b = Metric2d::fromAngle(0.4, 0.3, 2.0);
  const MetricAngle2d m = interpolate(a, b, 0.25).angleLengths();
  EXPECT_NEAR(m.h1, 0.15, 1e-13);
  EXPECT_NEAR(m.h2, 1.25, 1e-12);
  EXPECT_NEAR(m.alpha, 0.4, 1e-12);
}

TEST(MetricInterpolation, WeightedNPoint) {
  std::mt19937 rng(5);
  const Metric2d a = randomMetric2d(rng), b = randomMetric2d(rng);
  // Two points with weights (1 − t, t) and any positive scale equal eq. 2.18.
  const std::vector<Metric2d> ms{a, b};
  const std::vector<double> w{3 * 0.7, 3 * 0.3};
  EXPECT_LT((interpolate(ms, w).matrix() - interpolate(a, b, 0.3).matrix()).norm(), 1e-12 * a.matrix().norm());
  // Zero weights ignored; all-equal metrics reproduced.
  const Metric3d c = randomMetric3d(rng);
  const std::vector<Metric3d> cs{c, c, randomMetric3d(rng)};
  const std::vector<double> cw{0.2, 5.0, 0.0};
  EXPECT_LT((interpolate(cs, cw).matrix() - c.matrix()).norm(), 1e-11 * c.matrix().norm());
  // Blend accumulator.
  MetricBlend<2> blend;
  EXPECT_TRUE(blend.empty());
  EXPECT_THROW(blend.result(), MeshingError);
  blend.add(Metric2d::isotropic(1), 1);
  blend.add(Metric2d::isotropic(3), 1);
  EXPECT_NEAR(blend.result().lengthAlong(Vec2(0, 1)), 2.0, 1e-14);
  EXPECT_THROW(blend.add(Metric2d(), -1), MeshingError);
  EXPECT_THROW(blend.add(Metric2d(), std::nan("")), MeshingError);
}

TEST(MetricInterpolation, InvalidParameterThrows) {
  EXPECT_THROW(interpolate(Metric2d(), Metric2d(), 1.5), MeshingError);
  EXPECT_THROW(interpolate(Metric2d(), Metric2d(), std::nan("")), MeshingError);
  const std::vector<Metric2d> ms{Metric2d()};
  const std::vector<double> w{1.0, 2.0};
  EXPECT_THROW(interpolate(ms, w), MeshingError);
  const std::vector<double> zero{0.0};
  EXPECT_THROW(interpolate(ms, zero), MeshingError);
}

// ---- intersection ----

TEST(MetricIntersection, AnalyticCrossedEllipses) {
  // Ellipses (1 × 4) along x and along y: the largest ellipse inside both is the unit circle.
  const Metric2d a = Metric2d::fromAngle(0, 1, 4), b = Metric2d::fromAngle(M_PI / 2, 1, 4);
  const Metric2d r = intersect(a, b);
  EXPECT_LT((r.matrix() - Mat2::Identity()).norm(), 1e-12);
  // Isotropic: the smaller size wins, returned as that very input.
  const Metric3d s = Metric3d::isotropic(0.5), t = Metric3d::isotropic(2);
  EXPECT_EQ(intersect(s, t).matrix(), s.matrix());
  EXPECT_EQ(intersect(t, s).matrix(), s.matrix());
}

TEST(MetricIntersection, ContainedInBothAndTouchingEach2d) {
  std::mt19937 rng(11);
  const auto dirs = circleDirections(4000);
  int crossing = 0;
  for (int k = 0; k < 200; ++k) {
    const Metric2d a = randomMetric2d(rng), b = randomMetric2d(rng);
    const Metric2d r = intersect(a, b);
    // Containment: every vector is at least as long in r as in a and in b, i.e. the unit
    // ellipse of r lies inside both unit ellipses. Touching: equality in some direction.
    // Sampled: vectors of unit length in r have length ≤ 1 in a and in b, equivalently
    // every vector is at least as long in r as in a or b.
    EXPECT_LE(sampledRatio(r, a, dirs), 1 + 1e-10);
    EXPECT_LE(sampledRatio(r, b, dirs), 1 + 1e-10);
    EXPECT_GE(minRatio(r, a, dirs), 1 - 1e-10);
    EXPECT_GE(minRatio(r, b, dirs), 1 - 1e-10);
    checkTouching(r, a, b, crossing);
    // Commutative.
    EXPECT_LT((intersect(b, a).matrix() - r.matrix()).norm(), 1e-9 * r.matrix().norm());
  }
  EXPECT_GT(crossing, 50);  // enough pairs where neither ellipse contains the other
}

TEST(MetricIntersection, ContainedInBothAndTouchingEach3d) {
  std::mt19937 rng(13);
  const auto dirs = sphereDirections(10000);
  int crossing = 0;
  for (int k = 0; k < 40; ++k) {
    const Metric3d a = randomMetric3d(rng), b = randomMetric3d(rng);
    const Metric3d r = intersect(a, b);
    EXPECT_LE(sampledRatio(r, a, dirs), 1 + 1e-10);
    EXPECT_LE(sampledRatio(r, b, dirs), 1 + 1e-10);
    EXPECT_GE(minRatio(r, a, dirs), 1 - 1e-10);
    EXPECT_GE(minRatio(r, b, dirs), 1 - 1e-10);
    checkTouching(r, a, b, crossing);
  }
  EXPECT_GT(crossing, 10);
}

TEST(MetricIntersection, IntersectIntoReportsChange) {
  Metric2d fine = Metric2d::fromAngle(0.3, 0.1, 0.2);
  const Metric2d before = fine;
  EXPECT_FALSE(intersectInto(fine, Metric2d::isotropic(0.5)));  // coarser: unchanged
  EXPECT_EQ(fine.matrix(), before.matrix());
  Metric2d coarse = Metric2d::isotropic(1.0);
  EXPECT_TRUE(intersectInto(coarse, Metric2d::fromAngle(0, 0.5, 2.0)));
  EXPECT_NEAR(coarse.lengthAlong(Vec2(1, 0)), 0.5, 1e-12);
  EXPECT_NEAR(coarse.lengthAlong(Vec2(0, 1)), 1.0, 1e-12);
}

TEST(MetricIntersection, ManyMetrics) {
  std::mt19937 rng(17);
  const auto dirs = circleDirections(20000);
  std::vector<Metric2d> ms;
  for (int i = 0; i < 5; ++i) ms.push_back(randomMetric2d(rng));
  const Metric2d r = intersect(ms);
  double largest = 0;
  for (const Metric2d& m : ms) {
    EXPECT_GE(minRatio(r, m, dirs), 1 - 1e-10);
    EXPECT_LE(spectralRatio(r, m), 1 + 1e-9);
    largest = std::max(largest, spectralRatio(r, m));
  }
  EXPECT_NEAR(largest, 1.0, 1e-9);  // touches at least one input
  EXPECT_THROW(intersect(std::vector<Metric2d>{}), MeshingError);
}

// ---- comparison ----

TEST(MetricComparison, ZeroForEqualAndSymmetric) {
  std::mt19937 rng(19);
  for (int k = 0; k < 50; ++k) {
    const Metric2d a = randomMetric2d(rng), b = randomMetric2d(rng);
    EXPECT_NEAR(metricDifference(a, a), 0.0, 1e-12);
    EXPECT_EQ(metricDifference(a, b), metricDifference(b, a));
    EXPECT_GT(metricDifference(a, b), 0.0);
    const Metric3d c = randomMetric3d(rng), d = randomMetric3d(rng);
    EXPECT_NEAR(metricDifference(c, c), 0.0, 1e-11);
    EXPECT_EQ(metricDifference(c, d), metricDifference(d, c));
  }
}

TEST(MetricComparison, ScaledMetricAnalytic) {
  // δ_M(M, sM) = ‖(s + 1/s − 2) I‖ = √d |s + 1/s − 2|.
  const Metric2d m = Metric2d::fromAngle(0.5, 0.2, 0.7);
  for (double s : {0.5, 1.0, 2.0, 10.0})
    EXPECT_NEAR(metricDifference(m, m.scaled(s)), std::sqrt(2.0) * std::abs(s + 1 / s - 2), 1e-12);
  const Metric3d m3 = Metric3d::isotropic(0.3);
  EXPECT_NEAR(metricDifference(m3, m3.scaled(2)), std::sqrt(3.0) * 0.5, 1e-13);
}

// ---- anisotropy limit ----

TEST(MetricAnisotropy, LimitClampsLengthRatio) {
  const Metric2d m = Metric2d::fromAngle(0.3, 0.1, 2.0);
  const Metric2d l = limitAnisotropy(m, 5.0);
  const MetricAngle2d d = l.angleLengths();
  EXPECT_NEAR(d.h1, 0.1, 1e-13);
  EXPECT_NEAR(d.h2, 0.5, 1e-12);
  EXPECT_NEAR(d.alpha, 0.3, 1e-12);
  EXPECT_NEAR(anisotropyRatio(l), 5.0, 1e-10);
  // Within the limit: unchanged (the very same tensor).
  const Metric2d ok = Metric2d::fromAngle(0.3, 0.1, 0.3);
  EXPECT_EQ(limitAnisotropy(ok, 5.0).matrix(), ok.matrix());
  // γ_a = 1: isotropic at the smallest length.
  EXPECT_LT((limitAnisotropy(m, 1.0).matrix() - Mat2::Identity() / 0.1).norm(), 1e-10);
  EXPECT_THROW(limitAnisotropy(m, 0.5), MeshingError);
  EXPECT_THROW(limitAnisotropy(m, std::nan("")), MeshingError);
}

TEST(MetricAnisotropy, RandomMetricsSatisfyBoundAndOnlyRefine) {
  std::mt19937 rng(23);
  const auto dirs = sphereDirections(2000);
  for (int k = 0; k < 100; ++k) {
    const Metric3d m = randomMetric3d(rng);
    const Metric3d l = limitAnisotropy(m, 3.0);
    EXPECT_LE(anisotropyRatio(l), 3.0 * (1 + 1e-10));
    EXPECT_NEAR(l.axes().lengths(0), m.axes().lengths(0), 1e-10 * m.axes().lengths(0));
    EXPECT_GE(minRatio(l, m, dirs), 1 - 1e-10);  // never coarser
  }
  Vec3 h(1, 10, 4);
  EXPECT_TRUE(limitLengthRatio<3>(h, 2.0));
  EXPECT_EQ(h, Vec3(1, 2, 2));
}
