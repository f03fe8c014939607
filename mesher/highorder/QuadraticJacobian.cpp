// Jacobians of the quadratic tetrahedron, triangle and serendipity quad (QuadraticJacobian.h).
#include "mesher/highorder/QuadraticJacobian.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>

namespace aniso {
namespace {

constexpr int kTriEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int kTetEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

/// ∂x/∂L_i of a quadratic simplex in barycentric coordinates L: x_i (4 L_i − 1) plus 4 x_ij L_j
/// over the edges (i, j).
template <int N, int E>
std::array<Vec3, N> barycentricGradients(const std::array<Vec3, N>& corner, const std::array<Vec3, E>& mid,
                                         const int (&edges)[E][2], const std::array<double, N>& L) {
  std::array<Vec3, N> g;
  for (int i = 0; i < N; ++i) g[i] = corner[i] * (4 * L[i] - 1);
  for (int k = 0; k < E; ++k) {
    const int i = edges[k][0], j = edges[k][1];
    g[i] += 4 * L[j] * mid[k];
    g[j] += 4 * L[i] * mid[k];
  }
  return g;
}

/// The corners then the centroid of a simplex, in barycentric coordinates.
template <int N>
std::array<std::array<double, N>, N + 1> simplexSamples() {
  std::array<std::array<double, N>, N + 1> s{};
  for (int i = 0; i < N; ++i) s[i][i] = 1;
  s[N].fill(1.0 / N);
  return s;
}

}  // namespace

double tet10JacobianRatio(const std::array<Vec3, 4>& c, const std::array<Vec3, 6>& mid) {
  const double straight = (c[1] - c[0]).dot((c[2] - c[0]).cross(c[3] - c[0]));
  if (!(straight > 0)) return 0;
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& L : simplexSamples<4>()) {
    const std::array<Vec3, 4> g = barycentricGradients<4, 6>(c, mid, kTetEdges, L);
    const double det = (g[1] - g[0]).dot((g[2] - g[0]).cross(g[3] - g[0]));
    worst = std::min(worst, det);
  }
  return worst / straight;
}

double tri6JacobianRatio(const std::array<Vec3, 3>& c, const std::array<Vec3, 3>& mid) {
  const Vec3 n = (c[1] - c[0]).cross(c[2] - c[0]);
  const double straight = n.norm();
  if (!(straight > 0)) return 0;
  const Vec3 unit = n / straight;
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& L : simplexSamples<3>()) {
    const std::array<Vec3, 3> g = barycentricGradients<3, 3>(c, mid, kTriEdges, L);
    worst = std::min(worst, unit.dot((g[1] - g[0]).cross(g[2] - g[0])));
  }
  return worst / straight;
}

double quad8JacobianRatio(const std::array<Vec3, 4>& c, const std::array<Vec3, 4>& mid) {
  static constexpr double xi[4] = {-1, 1, 1, -1}, eta[4] = {-1, -1, 1, 1};
  const Vec3 diag = (c[2] - c[0]).cross(c[3] - c[1]);
  if (!(diag.norm() > 0)) return 0;
  const Vec3 n = diag.normalized();
  const Vec3 dxi = 0.25 * (c[1] + c[2] - c[0] - c[3]), deta = 0.25 * (c[2] + c[3] - c[0] - c[1]);
  const double straight = n.dot(dxi.cross(deta));
  if (!(straight > 0)) return 0;
  const double samples[5][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, 0}};
  double worst = std::numeric_limits<double>::infinity();
  for (const auto& s : samples) {
    const double x = s[0], y = s[1];
    Vec3 gx = Vec3::Zero(), gy = Vec3::Zero();
    for (int i = 0; i < 4; ++i) {  // corners: ¼ (1 + x xi)(1 + y yi)(x xi + y yi − 1)
      gx += 0.25 * xi[i] * (1 + y * eta[i]) * (2 * x * xi[i] + y * eta[i]) * c[i];
      gy += 0.25 * eta[i] * (1 + x * xi[i]) * (x * xi[i] + 2 * y * eta[i]) * c[i];
    }
    for (int k = 0; k < 4; ++k) {  // mid node k between corners k and k+1
      const double mx = 0.5 * (xi[k] + xi[(k + 1) % 4]), my = 0.5 * (eta[k] + eta[(k + 1) % 4]);
      if (mx == 0) {  // ½ (1 − x²)(1 + y my)
        gx += -x * (1 + y * my) * mid[k];
        gy += 0.5 * (1 - x * x) * my * mid[k];
      } else {  // ½ (1 + x mx)(1 − y²)
        gx += 0.5 * mx * (1 - y * y) * mid[k];
        gy += -y * (1 + x * mx) * mid[k];
      }
    }
    worst = std::min(worst, n.dot(gx.cross(gy)));
  }
  return worst / straight;
}

}  // namespace aniso
