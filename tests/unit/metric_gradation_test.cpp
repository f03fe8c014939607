// Tests of the metric gradation smoothing (sec. 2.3.4, eq. 2.26–2.32).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/metric/MetricGradation.h"

using namespace aniso;

namespace {

/// Largest length ratio h_a(u) / h_b(u) over sampled directions u (both ways).
template <int D, class Dirs>
double worstLengthRatio(const Metric<D>& a, const Metric<D>& b, const Dirs& dirs) {
  double worst = 1;
  for (const auto& u : dirs) {
    const double ha = a.lengthAlong(u), hb = b.lengthAlong(u);
    worst = std::max({worst, ha / hb, hb / ha});
  }
  return worst;
}

std::vector<Vec2> circleDirections(int n) {
  std::vector<Vec2> d;
  for (int i = 0; i < n; ++i) d.emplace_back(std::cos(M_PI * i / n), std::sin(M_PI * i / n));
  return d;
}

std::vector<Vec3> sphereDirections(int n) {
  std::vector<Vec3> d;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z);
    d.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return d;
}

struct Pair {
  int a, b;
};

/// Sweeps smoothGradation over all pairs until nothing changes; returns the sweep count.
template <int D, class Points>
int smoothToConvergence(std::vector<Metric<D>>& ms, const Points& pts, const std::vector<Pair>& pairs,
                        const GradationRule& rule, int maxSweeps) {
  for (int sweep = 1; sweep <= maxSweeps; ++sweep) {
    bool changed = false;
    for (const Pair& p : pairs) {
      const Eigen::Matrix<double, D, 1> d = pts[p.b] - pts[p.a];
      changed = smoothGradation(ms[p.a], ms[p.b], d, rule) || changed;
    }
    if (!changed) return sweep;
  }
  return -1;
}

/// Checks the bound of the header for every pair; returns how many pairs violate it.
template <int D, class Points, class Dirs>
int countViolations(const std::vector<Metric<D>>& ms, const Points& pts, const std::vector<Pair>& pairs,
                    double gamma, const Dirs& dirs, double tol) {
  int bad = 0;
  for (const Pair& p : pairs) {
    const Eigen::Matrix<double, D, 1> d = pts[p.b] - pts[p.a];
    const double ha = ms[p.a].lengthAlong(d), hb = ms[p.b].lengthAlong(d);
    const double s = gradationFactor(ha, hb, d.norm(), gamma);
    // Verbal bound of sec. 2.3.4: the ratio over a unit metric distance is at most γ_M,
    // i.e. at most 1 + (γ_M − 1) d / h_min along the segment.
    const double bound = 1 + (gamma - 1) * d.norm() / std::min(ha, hb);
    EXPECT_LE(s, bound * (1 + 1e-12));
    const double worst = worstLengthRatio(ms[p.a], ms[p.b], dirs);
    if (worst > s * (1 + tol) || worst > bound * (1 + tol)) ++bad;
  }
  return bad;
}

}  // namespace

TEST(MetricGradation, CoefficientsOfEquations) {
  EXPECT_NEAR(gradationSlopeLimit(4.0), 1.2, 1e-15);  // 2 (4 − 1) / (4 + 1)
  EXPECT_EQ(gradationSlopeLimit(1.0), 0.0);
  EXPECT_THROW(gradationSlopeLimit(0.5), MeshingError);
  // a = 0 (equal lengths): s = 1 + (γ − 1) d / h.
  EXPECT_NEAR(gradationFactor(0.5, 0.5, 0.5, 3.0), 3.0, 1e-15);
  EXPECT_NEAR(gradationFactor(0.5, 0.5, 0.25, 3.0), 2.0, 1e-15);
  // a clipped to a_max: s = 1 + (γ − 1)(1 − a_max/2) d / h_min = 1 + a_max d / h_min.
  EXPECT_NEAR(gradationFactor(0.1, 10, 1, 2.0), 1 + (2.0 / 3) * 10, 1e-12);
  // Unclipped: a = 0.5, s = 1 + 1·(1 − 0.25)·1/1.
  EXPECT_NEAR(gradationFactor(1.0, 1.5, 1.0, 2.0), 1.75, 1e-15);
  EXPECT_EQ(gradationFactor(1.0, 2.0, 0.0, 2.0), 1.0);
}

TEST(MetricGradation, OneDimensionalGrowth) {
  // h = 0.1 at x = 0 and h = 10 at x = 1, γ_M = 2: the coarse metric is limited to
  // s · 0.1 with s = 1 + a_max · 1 / 0.1, the fine one is kept.
  Metric2d fine = Metric2d::isotropic(0.1), coarse = Metric2d::isotropic(10);
  const GradationRule rule{2.0, 0.0, 1e-12};
  EXPECT_TRUE(smoothGradation(fine, coarse, Vec2(1, 0), rule));
  EXPECT_NEAR(fine.lengthAlong(Vec2(1, 0)), 0.1, 1e-15);
  const double expected = 0.1 * (1 + (2.0 / 3) * 10);
  EXPECT_NEAR(coarse.lengthAlong(Vec2(1, 0)), expected, 1e-12);
  EXPECT_NEAR(coarse.lengthAlong(Vec2(1, 1)), expected, 1e-12);  // isotropic stays isotropic
  // A second application changes nothing.
  EXPECT_FALSE(smoothGradation(fine, coarse, Vec2(1, 0), rule));
}

TEST(MetricGradation, AnisotropicTransverseDirectionIsLimitedToo) {
  // Along the segment both request 0.1, across one requests 0.1 and the other 5.
  Metric2d a = Metric2d::isotropic(0.1), b = Metric2d::fromAngle(0, 0.1, 5.0);
  const GradationRule rule{1.5, 0.0, 1e-12};
  EXPECT_TRUE(smoothGradation(a, b, Vec2(0.1, 0), rule));
  const double s = 1 + 0.5 * 0.1 / 0.1;  // a = 0
  EXPECT_NEAR(b.lengthAlong(Vec2(0, 1)), s * 0.1, 1e-12);
  EXPECT_NEAR(b.lengthAlong(Vec2(1, 0)), 0.1, 1e-12);
  EXPECT_NEAR(a.lengthAlong(Vec2(0, 1)), 0.1, 1e-14);
}

TEST(MetricGradation, SkipsSimilarMetricsWhenAsked) {
  Metric2d a = Metric2d::isotropic(1.0), b = Metric2d::isotropic(1.05);
  const Metric2d b0 = b;
  GradationRule rule{1.01, 0.5, 1e-12};  // δ_M(a, b) ≈ 0.003 < 0.5: skipped
  EXPECT_FALSE(smoothGradation(a, b, Vec2(1e-3, 0), rule));
  EXPECT_EQ(b.matrix(), b0.matrix());
  rule.skipDifference = 0;
  EXPECT_TRUE(smoothGradation(a, b, Vec2(1e-3, 0), rule));
  EXPECT_THROW(smoothGradation(a, b, Vec2(std::nan(""), 0), rule), MeshingError);
}

TEST(MetricGradation, RandomGridConverges2d) {
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), logh(-2.5, -0.3), stretch(0, 1);
  const int n = 10;
  const double spacing = 0.1;
  std::vector<Vec2> pts;
  std::vector<Metric2d> ms;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      pts.emplace_back(i * spacing, j * spacing);
      const double h = std::pow(10, logh(rng));
      ms.push_back(Metric2d::fromAngle(angle(rng), h, h * std::pow(10, stretch(rng))));
    }
  }
  std::vector<Pair> pairs;  // 4- and 8-neighbours
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int k = j * n + i;
      if (i + 1 < n) pairs.push_back({k, k + 1});
      if (j + 1 < n) pairs.push_back({k, k + n});
      if (i + 1 < n && j + 1 < n) pairs.push_back({k, k + n + 1});
      if (i > 0 && j + 1 < n) pairs.push_back({k, k + n - 1});
    }
  }
  const std::vector<Metric2d> initial = ms;
  const double gamma = 1.8;
  const auto dirs = circleDirections(720);
  // The random field violates the bound (else the test would prove nothing).
  EXPECT_GT(countViolations(ms, pts, pairs, gamma, dirs, 1e-6), int(pairs.size()) / 4);

  const int sweeps = smoothToConvergence(ms, pts, pairs, GradationRule{gamma, 0.0, 1e-10}, 2000);
  ASSERT_GT(sweeps, 0) << "gradation smoothing did not converge";
  EXPECT_EQ(countViolations(ms, pts, pairs, gamma, dirs, 1e-6), 0);
  // Smoothing only refines: no length grew.
  for (std::size_t k = 0; k < ms.size(); ++k)
    for (const Vec2& u : dirs) EXPECT_LE(ms[k].lengthAlong(u), initial[k].lengthAlong(u) * (1 + 1e-9));
}

TEST(MetricGradation, RandomGridConverges3d) {
  std::mt19937 rng(31);
  std::normal_distribution<double> nd;
  std::uniform_real_distribution<double> logh(-2, -0.3);
  const int n = 4;
  std::vector<Vec3> pts;
  std::vector<Metric3d> ms;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        pts.emplace_back(0.2 * i, 0.2 * j, 0.2 * k);
        const Mat3 r = Eigen::Quaterniond(nd(rng), nd(rng), nd(rng), nd(rng)).normalized().toRotationMatrix();
        ms.push_back(Metric3d::fromDirections(r.col(0), r.col(1), r.col(2), std::pow(10, logh(rng)),
                                              std::pow(10, logh(rng)), std::pow(10, logh(rng))));
      }
  std::vector<Pair> pairs;
  auto id = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (i + 1 < n) pairs.push_back({id(i, j, k), id(i + 1, j, k)});
        if (j + 1 < n) pairs.push_back({id(i, j, k), id(i, j + 1, k)});
        if (k + 1 < n) pairs.push_back({id(i, j, k), id(i, j, k + 1)});
      }
  const double gamma = 2.0;
  const auto dirs = sphereDirections(1500);
  EXPECT_GT(countViolations(ms, pts, pairs, gamma, dirs, 1e-6), 0);
  const int sweeps = smoothToConvergence(ms, pts, pairs, GradationRule{gamma, 0.0, 1e-10}, 2000);
  ASSERT_GT(sweeps, 0) << "gradation smoothing did not converge";
  EXPECT_EQ(countViolations(ms, pts, pairs, gamma, dirs, 1e-6), 0);
}
