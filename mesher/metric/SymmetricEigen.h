#pragma once
// Small symmetric-matrix kernels behind the metric module (sec. 2.3.2: "the eigensystem
// for both two- and three-dimensional matrices can be calculated by directly solving the
// characteristic equation").
//
// - symmetricEigen(A): eigenvalues (ascending) and orthonormal eigenvectors (columns) of a
//   symmetric 2×2 (closed form) or 3×3 (Eigen's fixed-size SelfAdjointEigenSolver, no
//   heap allocation) matrix. Only the lower triangle is read in 3D; in 2D A(0,1) is used.
// - isSymmetricPositiveDefinite(A): finite, and Sylvester's criterion holds.
// - symmetrize(A): ½(A + Aᵀ).
// None of these throws; callers decide what a failure means.
#include <Eigen/Eigenvalues>
#include <cmath>

#include "mesher/core/Types.h"

namespace aniso {

template <int D>
struct SymmetricEigen {
  Eigen::Matrix<double, D, 1> values;   ///< ascending
  Eigen::Matrix<double, D, D> vectors;  ///< column i is the unit eigenvector of values(i)
};

/// Closed form for 2×2: with θ = ½ atan2(2b, a − c) the larger eigenvalue belongs to
/// (cos θ, sin θ) — exactly the angle α of eq. 2.4 when A = R diag(1/h1, 1/h2) Rᵀ, h1 < h2.
/// A multiple of the identity gives θ = 0 (the u / x axis).
inline SymmetricEigen<2> symmetricEigen(const Mat2& a) {
  const double b = a(0, 1);
  const double mean = 0.5 * (a(0, 0) + a(1, 1));
  const double half = 0.5 * (a(0, 0) - a(1, 1));
  const double r = std::hypot(half, b);
  const double theta = 0.5 * std::atan2(b, half);
  const double c = std::cos(theta), s = std::sin(theta);
  SymmetricEigen<2> e;
  e.values << mean - r, mean + r;
  e.vectors << -s, c, c, s;
  return e;
}

inline SymmetricEigen<3> symmetricEigen(const Mat3& a) {
  Eigen::SelfAdjointEigenSolver<Mat3> solver(a, Eigen::ComputeEigenvectors);
  return {solver.eigenvalues(), solver.eigenvectors()};
}

template <int D>
inline Eigen::Matrix<double, D, D> symmetrize(const Eigen::Matrix<double, D, D>& a) {
  return 0.5 * (a + a.transpose());
}

inline bool isSymmetricPositiveDefinite(const Mat2& a) {
  return a.allFinite() && a(0, 0) > 0 && a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0) > 0;
}

inline bool isSymmetricPositiveDefinite(const Mat3& a) {
  if (!a.allFinite() || !(a(0, 0) > 0)) return false;
  const double minor2 = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
  return minor2 > 0 && a.determinant() > 0;
}

}  // namespace aniso
