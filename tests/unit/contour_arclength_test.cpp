// contour::MetricArcLength: adaptive sampling of a metric density and the inverse of its
// arc length (thesis alg. 4.1 steps 2–3).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "mesher/core/Error.h"
#include "mesher/surface/contour/MetricArcLength.h"

using aniso::MeshingError;
using aniso::contour::MetricArcLength;

TEST(ContourArcLength, ConstantDensityIsExact) {
  const MetricArcLength a([](double) { return 4.0; }, 1.0, 3.0);
  EXPECT_DOUBLE_EQ(a.total(), 8.0);
  const std::vector<double> t = a.equalSpacing(8);
  ASSERT_EQ(t.size(), 9u);
  for (int i = 0; i <= 8; ++i) EXPECT_NEAR(t[i], 1.0 + 0.25 * i, 1e-14);
  EXPECT_EQ(t.front(), 1.0);
  EXPECT_EQ(t.back(), 3.0);
}

TEST(ContourArcLength, LinearDensityInvertsExactly) {
  // ρ = t on [0, 1]: s(t) = t²/2, so s⁻¹(s) = √(2s). A piecewise-linear model is exact.
  const MetricArcLength a([](double t) { return t; }, 0.0, 1.0);
  EXPECT_NEAR(a.total(), 0.5, 1e-14);
  for (double s : {0.01, 0.1, 0.25, 0.4, 0.49}) EXPECT_NEAR(a.parameterAt(s), std::sqrt(2 * s), 1e-12) << s;
  EXPECT_EQ(a.parameterAt(-1), 0.0);
  EXPECT_EQ(a.parameterAt(7), 1.0);
}

TEST(ContourArcLength, NarrowBumpIsResolved) {
  // ρ = 1 + 100 exp(−((t − 0.53)/0.01)²): ∫ over [0, 1] = 1 + √π (to 1e-15).
  const auto rho = [](double t) { return 1 + 100 * std::exp(-std::pow((t - 0.53) / 0.01, 2)); };
  const MetricArcLength a(rho, 0.0, 1.0);
  const double exact = 1 + std::sqrt(std::numbers::pi);
  EXPECT_NEAR(a.total(), exact, 2e-3 * exact);
  // Equal spacing: every piece has the same metric length (checked by fine quadrature).
  const std::vector<double> t = a.equalSpacing(5);
  for (int i = 0; i < 5; ++i) {
    double s = 0;
    const int n = 20000;
    for (int k = 0; k < n; ++k) s += rho(t[i] + (k + 0.5) * (t[i + 1] - t[i]) / n) * (t[i + 1] - t[i]) / n;
    EXPECT_NEAR(s, exact / 5, 2e-3 * exact) << "piece " << i;
  }
}

TEST(ContourArcLength, PiecesAreShortInTheMetric) {
  // A long curve in the metric is sampled at least 4 times per unit of length.
  const MetricArcLength a([](double) { return 1.0; }, 0.0, 100.0);
  EXPECT_GE(a.samples(), 400);
  EXPECT_NEAR(a.total(), 100.0, 1e-10);
}

TEST(ContourArcLength, ZeroDensityFallsBackToParameterSpacing) {
  const MetricArcLength a([](double) { return 0.0; }, 0.0, 2.0);
  EXPECT_EQ(a.total(), 0.0);
  const std::vector<double> t = a.equalSpacing(4);
  for (int i = 0; i <= 4; ++i) EXPECT_DOUBLE_EQ(t[i], 0.5 * i);
}

TEST(ContourArcLength, RejectsBadInput) {
  EXPECT_THROW(MetricArcLength([](double) { return 1.0; }, 1.0, 1.0), MeshingError);
  EXPECT_THROW(MetricArcLength([](double) { return 1.0; }, 0.0, std::numeric_limits<double>::infinity()), MeshingError);
  EXPECT_THROW(MetricArcLength([](double t) { return t > 0.5 ? std::nan("") : 1.0; }, 0.0, 1.0), MeshingError);
  EXPECT_THROW(MetricArcLength([](double) { return -1.0; }, 0.0, 1.0), MeshingError);
}
