// Tests of the metric value types (sec. 2.2): eq. 2.4/2.15 construction, 𝓜 = M Mᵀ (2.19),
// decomposition back, P^M = M P and distances (2.10, 2.11), the midpoint rule (2.14) and
// the surface spaces S^R, S^M (2.9–2.13).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "mesher/core/Error.h"
#include "mesher/metric/Metric.h"
#include "mesher/metric/MetricLength.h"
#include "mesher/metric/SurfaceMetric.h"

using namespace aniso;

namespace {

/// Difference of two angles of undirected axes (modulo π), in [0, π/2].
double axisAngleDiff(double a, double b) {
  double d = std::fmod(std::abs(a - b), M_PI);
  return std::min(d, M_PI - d);
}

Mat3 randomRotation(std::mt19937& rng) {
  std::normal_distribution<double> n;
  Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  q.normalize();
  return q.toRotationMatrix();
}

}  // namespace

TEST(MetricTensor, Equation24Entries) {
  const double a = 0.4, h1 = 0.5, h2 = 3.0;
  const Mat2 m = Metric2d::fromAngle(a, h1, h2).matrix();
  const double c = std::cos(a), s = std::sin(a);
  EXPECT_NEAR(m(0, 0), c * c / h1 + s * s / h2, 1e-15);
  EXPECT_NEAR(m(0, 1), (1 / h1 - 1 / h2) * s * c, 1e-15);
  EXPECT_NEAR(m(1, 0), m(0, 1), 0);
  EXPECT_NEAR(m(1, 1), s * s / h1 + c * c / h2, 1e-15);
  // e1 = (cos α, sin α) is scaled by 1/h1, e2 by 1/h2: unit metric length at h_i.
  const Metric2d metric = Metric2d::fromAngle(a, h1, h2);
  EXPECT_NEAR(metric.length(Vec2(c, s) * h1), 1.0, 1e-14);
  EXPECT_NEAR(metric.length(Vec2(-s, c) * h2), 1.0, 1e-14);
  EXPECT_NEAR(metric.lengthAlong(Vec2(c, s)), h1, 1e-14);
  EXPECT_NEAR(metric.determinant(), 1 / (h1 * h2), 1e-14);
}

TEST(MetricTensor, RoundTripAngleLengthsThroughMetricTensor2d) {
  const double angles[] = {0.0, 0.3, -1.2, M_PI / 2, 2.9, -3.0};
  const double lengths[][2] = {{1, 1}, {0.1, 0.4}, {1e-3, 1.0}, {2.0, 2.0 + 1e-6}, {5, 50}};
  for (double alpha : angles) {
    for (const auto& h : lengths) {
      const Metric2d m = Metric2d::fromAngle(alpha, h[0], h[1]);
      const Mat2 t = m.tensor();  // eq. 2.19
      EXPECT_LT((t - m.matrix() * m.matrix().transpose()).norm(), 1e-12 * t.norm());
      const Metric2d back = Metric2d::fromTensor(t);
      EXPECT_LT((back.matrix() - m.matrix()).norm(), 1e-10 * m.matrix().norm());
      const MetricAngle2d d = back.angleLengths();
      EXPECT_NEAR(d.h1, h[0], 1e-9 * h[0]);
      EXPECT_NEAR(d.h2, h[1], 1e-9 * h[1]);
      EXPECT_GT(d.alpha, -M_PI / 2 - 1e-15);
      EXPECT_LE(d.alpha, M_PI / 2);
      if (h[1] / h[0] > 1.01) {
        EXPECT_LT(axisAngleDiff(d.alpha, alpha), 1e-9) << alpha;
      }
    }
  }
}

TEST(MetricTensor, DecompositionOrdersLengths) {
  // h1 > h2 given: the decomposition reports the smaller length first, rotated by π/2.
  const MetricAngle2d d = Metric2d::fromAngle(0.2, 3.0, 1.0).angleLengths();
  EXPECT_NEAR(d.h1, 1.0, 1e-12);
  EXPECT_NEAR(d.h2, 3.0, 1e-12);
  EXPECT_LT(axisAngleDiff(d.alpha, 0.2 + M_PI / 2), 1e-12);
}

TEST(MetricTensor, RoundTripDirectionsLengths3d) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> logh(-3, 1);
  for (int k = 0; k < 50; ++k) {
    const Mat3 r = randomRotation(rng);
    Vec3 h(std::pow(10, logh(rng)), std::pow(10, logh(rng)), std::pow(10, logh(rng)));
    const Metric3d m = Metric3d::fromDirections(r.col(0), r.col(1), r.col(2), h(0), h(1), h(2));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.length(r.col(i) * h(i)), 1.0, 1e-12);
    const Metric3d back = Metric3d::fromTensor(m.tensor());
    EXPECT_LT((back.matrix() - m.matrix()).norm(), 1e-9 * m.matrix().norm());
    const MetricAxes<3> a = back.axes();
    EXPECT_LT(a.lengths(0), a.lengths(1) + 1e-15);
    EXPECT_LT(a.lengths(1), a.lengths(2) + 1e-15);
    EXPECT_NEAR(a.directions.determinant(), 1.0, 1e-12);
    // Same lengths, each along its own direction (directions up to sign).
    Vec3 sorted = h;
    std::sort(sorted.data(), sorted.data() + 3);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(a.lengths(i), sorted(i), 1e-8 * sorted(i));
      EXPECT_NEAR(back.lengthAlong(a.directions.col(i)), a.lengths(i), 1e-8 * a.lengths(i));
    }
    // fromAxes reproduces the metric.
    EXPECT_LT((Metric3d::fromAxes(a.directions, a.lengths).matrix() - m.matrix()).norm(),
              1e-9 * m.matrix().norm());
  }
}

TEST(MetricTensor, IdentityAndIsotropic) {
  EXPECT_EQ(Metric2d().matrix(), Mat2::Identity());
  EXPECT_EQ(Metric3d::identity().matrix(), Mat3::Identity());
  const Metric3d iso = Metric3d::isotropic(0.25);
  EXPECT_NEAR(iso.distance(Vec3(1, 1, 1), Vec3(1, 1, 2)), 4.0, 1e-15);
  EXPECT_NEAR(Metric2d::isotropic(2).scaled(4).lengthAlong(Vec2(1, 1)), 0.5, 1e-15);
  EXPECT_EQ(Metric2d::isotropic(0.5).apply(Vec2(1, -2)), Vec2(2, -4));  // P^M = M P
}

TEST(MetricTensor, InvalidInputThrows) {
  EXPECT_THROW(Metric2d::fromAngle(0, -1, 1), MeshingError);
  EXPECT_THROW(Metric2d::fromAngle(0, 1, 0), MeshingError);
  EXPECT_THROW(Metric2d::fromAngle(std::nan(""), 1, 1), MeshingError);
  EXPECT_THROW(Metric2d::fromAngle(0, 1, INFINITY), MeshingError);
  EXPECT_THROW(Metric2d::isotropic(std::nan("")), MeshingError);
  Mat2 nonSym;
  nonSym << 1, 0.5, 0, 1;
  EXPECT_THROW(Metric2d::fromTransformation(nonSym), MeshingError);
  Mat2 indefinite;
  indefinite << 1, 2, 2, 1;
  EXPECT_THROW(Metric2d::fromTransformation(indefinite), MeshingError);
  EXPECT_THROW(Metric2d::fromTensor(indefinite), MeshingError);
  EXPECT_THROW(Metric2d::fromTensor(Mat2::Zero()), MeshingError);
  Mat3 nan3 = Mat3::Identity();
  nan3(1, 1) = std::nan("");
  EXPECT_THROW(Metric3d::fromTensor(nan3), MeshingError);
  EXPECT_THROW(Metric3d::fromDirections(Vec3::UnitX(), Vec3(1, 1, 0), Vec3::UnitZ(), 1, 1, 1), MeshingError);
  EXPECT_THROW(Metric3d::fromDirections(Vec3::UnitX(), Vec3::Zero(), Vec3::UnitZ(), 1, 1, 1), MeshingError);
  EXPECT_THROW(Metric2d::identity().scaled(0), MeshingError);
  EXPECT_THROW(Metric2d::identity().scaled(-2), MeshingError);
  // Valid near-limit input is accepted.
  EXPECT_NO_THROW(Metric2d::fromAngle(0.1, 1e-6, 1e3));
}

TEST(MetricTensor, ConstantMetricDistance) {
  const Metric2d m = Metric2d::fromAngle(M_PI / 6, 0.1, 1.0);
  const Vec2 e1(std::cos(M_PI / 6), std::sin(M_PI / 6)), e2(-e1.y(), e1.x());
  const Vec2 a(0.3, -0.2);
  EXPECT_NEAR(m.distance(a, a + 0.3 * e1), 3.0, 1e-13);   // eq. 2.11 along e1
  EXPECT_NEAR(m.distance(a, a + 0.3 * e2), 0.3, 1e-13);   // along e2
  EXPECT_NEAR(metricLength(m, a, Vec2(a + 0.3 * e1)), 3.0, 1e-13);
  EXPECT_NEAR((m.apply(a + e1) - m.apply(a)).norm(), m.distance(a, a + e1), 1e-14);
}

TEST(MetricTensor, MidpointRuleAndVariableMetric) {
  // Isotropic h(x) = 1 + x along [0, 2]: midpoint rule gives 2 / h(1) = 1 (eq. 2.14);
  // the exact integral ∫ dx / (1 + x) = ln 3.
  auto field = [](const Vec2& p) { return Metric2d::isotropic(1 + p.x()); };
  const Vec2 a(0, 0), b(2, 0);
  EXPECT_NEAR(metricLengthMidpoint(field, a, b), 1.0, 1e-14);
  EXPECT_NEAR(metricLengthGauss(field, a, b), std::log(3.0), 2e-3);
  // A field returning a general (surface) transformation matrix works the same way.
  auto matField = [](const Vec2& p) { return Mat2(Mat2::Identity() / (1 + p.x())); };
  EXPECT_NEAR(metricLengthMidpoint(matField, a, b), 1.0, 1e-14);
  // Constant field: all rules agree with eq. 2.11.
  auto constField = [](const Vec3&) { return Metric3d::isotropic(0.5); };
  EXPECT_NEAR(metricLengthGauss(constField, Vec3(0, 0, 0), Vec3(0, 3, 4)), 10.0, 1e-13);
}

TEST(MetricTensor, SurfaceSpaces) {
  // Sheared parameterization: G = Mp², Mp symmetric SPD.
  Mat2 mp;
  mp << 2.0, 0.5, 0.5, 1.0;
  const Metric2d ms = Metric2d::fromAngle(0.7, 0.2, 0.8);
  const Mat2 m = surfaceTransformation(ms, mp);  // eq. 2.9
  const Vec2 p1(0.1, 0.2), p2(0.4, -0.3);
  EXPECT_NEAR(metricDistance(m, p1, p2), ms.length(mp * (p2 - p1)), 1e-14);  // 2.10, 2.11
  EXPECT_NEAR(realDistance(mp, p1, p2), (toRealSpace(mp, p2) - toRealSpace(mp, p1)).norm(), 1e-15);
  EXPECT_NEAR((toMetricSpace(m, p2) - toMetricSpace(m, p1)).norm(), metricDistance(m, p1, p2), 1e-14);
  // M_s is recovered from M = M_s M_p.
  EXPECT_LT((sizingComponent(m, mp).matrix() - ms.matrix()).norm(), 1e-13);
  // The angle of a parametric direction is measured in S^R.
  const Vec2 y(1, -1);
  const Vec2 e = mp * y;
  EXPECT_NEAR(angleInRealSpace(mp, y), std::atan2(e.y(), e.x()), 1e-15);
  EXPECT_THROW(angleInRealSpace(Mat2::Zero(), y), MeshingError);
  EXPECT_THROW(angleInRealSpace(mp, Vec2::Zero()), MeshingError);
}
