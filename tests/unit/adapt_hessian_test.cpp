// Tests of the Hessian recovery and the Lp metric (mesher/adapt/): the least-squares fit is
// exact for quadratics at every node of a perturbed (random) tet and triangle mesh, the
// double L2 projection is not at the boundary; the Lp metric meets its node count, its
// bounds and its anisotropy limit, and is stretched along the level sets of a front.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Geometry>

#include "mesher/adapt/HessianRecovery.h"
#include "mesher/adapt/LpMetric.h"
#include "mesher/core/Error.h"
#include "tests/unit/adapt_fixtures.h"

namespace aniso {
namespace {

double quadratic(const Vec3& x) {
  return 1 + 2 * x.x() - x.y() + 3 * x.x() * x.x() + 1.5 * x.x() * x.y() - 2 * x.z() * x.z() + 0.7 * x.y() * x.z() -
         0.4 * x.x() * x.z() + x.y() * x.y();
}

Mat3 quadraticHessian() {
  Mat3 h;
  h << 6, 1.5, -0.4, 1.5, 2, 0.7, -0.4, 0.7, -4;
  return h;
}

std::vector<double> sample(const PatchMesh& m, double (*f)(const Vec3&)) {
  std::vector<double> v;
  for (const Vec3& p : m.nodes) v.push_back(f(p));
  return v;
}

TEST(AdaptHessian, LeastSquaresIsExactForAQuadraticOnARandomTetMesh) {
  const PatchMesh m = randomMesh(3, 6, 7);
  const std::vector<Mat3> h = recoverHessian(m, sample(m, quadratic));
  const std::vector<Mat3> l2 = recoverHessian(m, sample(m, quadratic), HessianMethod::DoubleL2);
  const std::vector<char> boundary = boundaryNodes(m);
  double worst = 0, worstL2Boundary = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    worst = std::max(worst, (h[i] - quadraticHessian()).cwiseAbs().maxCoeff());
    if (boundary[i]) worstL2Boundary = std::max(worstL2Boundary, (l2[i] - quadraticHessian()).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-8);
  // the double L2 projection loses its order at the boundary: why least squares is the default
  EXPECT_GT(worstL2Boundary, 1.0);
}

TEST(AdaptHessian, LeastSquaresIsExactInTheTangentPlaneOfATriangleMesh) {
  const PatchMesh m = randomMesh(2, 10, 3);
  // f = 3 s² − s t + 2 t² in an orthonormal frame of the plane; H₂ = [[6, −1], [−1, 4]]
  const Vec3 n = Vec3(-0.3, -0.1, 1).normalized();
  const Vec3 s = Vec3(1, 0, 0.3).normalized(), t = n.cross(s);
  std::vector<double> f;
  for (const Vec3& p : m.nodes) {
    const double a = p.dot(s), b = p.dot(t);
    f.push_back(3 * a * a - a * b + 2 * b * b + a);
  }
  Eigen::Matrix<double, 3, 2> frame;
  frame.col(0) = s;
  frame.col(1) = t;
  Mat2 h2;
  h2 << 6, -1, -1, 4;
  const Mat3 expected = frame * h2 * frame.transpose();
  double worst = 0;
  for (const Mat3& h : recoverHessian(m, f)) worst = std::max(worst, (h - expected).cwiseAbs().maxCoeff());
  EXPECT_LT(worst, 1e-8);
}

/// A front at x = 0.5 the mesh resolves: |f''| peaks at |x − 0.5| ≈ 0.16.
double front(const Vec3& x) { return std::tanh(4 * (x.x() - 0.5)); }

TEST(AdaptHessian, LpMetricMeetsTheNodeCountBoundsAndAnisotropy) {
  const PatchMesh m = randomMesh(3, 8, 11);
  const std::vector<Mat3> h = recoverHessian(m, sample(m, front));
  LpMetricParameters p;
  p.dim = 3;
  p.targetNodes = 5000;
  p.hmin = 1e-3;
  p.hmax = 0.5;
  p.anisotropy = 8;
  const LpMetric lm = lpMetric(h, nodeMeasures(m), {}, {}, p);
  EXPECT_FALSE(lm.limited);
  EXPECT_NEAR(lm.predictedNodes, 5000, 1);
  double stretchedAtFront = 0;
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    const auto ax = lm.metrics[i].axes();
    const double lo = ax.lengths.minCoeff(), hi = ax.lengths.maxCoeff();
    EXPECT_GE(lo, p.hmin * (1 - 1e-9));
    EXPECT_LE(hi, p.hmax * (1 + 1e-9));
    EXPECT_LE(hi / lo, p.anisotropy * (1 + 1e-9));
    if (std::abs(std::abs(m.nodes[i].x() - 0.5) - 0.17) < 0.08) {
      // the short axis across the front (along x)
      Eigen::Index k;
      ax.lengths.minCoeff(&k);
      EXPECT_GT(std::abs(ax.directions.col(k).x()), 0.9);
      stretchedAtFront = std::max(stretchedAtFront, hi / lo);
    }
  }
  EXPECT_GT(stretchedAtFront, 4);
  // the same metric asked by its predicted error gives the same count
  LpMetricParameters q = p;
  q.targetNodes = 0;
  q.error = lm.predictedError;
  EXPECT_NEAR(lpMetric(h, nodeMeasures(m), {}, {}, q).predictedNodes, 5000, 5);
}

TEST(AdaptHessian, LinearFieldIsRefused) {
  const PatchMesh m = randomMesh(3, 3, 1);
  LpMetricParameters p;
  p.targetNodes = 100;
  p.hmin = 0.01;
  p.hmax = 1;
  std::vector<Mat3> zero(m.nodes.size(), Mat3::Zero());
  EXPECT_THROW(lpMetric(zero, nodeMeasures(m), {}, {}, p), MeshingError);
}

}  // namespace
}  // namespace aniso
