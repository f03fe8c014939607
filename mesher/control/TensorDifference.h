#pragma once
// δ_M of eq. 2.24–2.25 (MetricComparison.h) for two symmetric positive-definite matrices
// that are not Metric objects, e.g. parameterization tensors M_p (sec. 3.3.3):
//   δ(A, B) = ‖A⁻¹B + B⁻¹A − 2I‖ (Frobenius). Inline, no checks: A and B must be SPD.
#include <Eigen/LU>

#include "mesher/core/Types.h"

namespace aniso {

template <int D>
inline double tensorDifference(const Eigen::Matrix<double, D, D>& a, const Eigen::Matrix<double, D, D>& b) {
  using Mat = Eigen::Matrix<double, D, D>;
  return (a.inverse() * b + b.inverse() * a - 2 * Mat::Identity()).norm();
}

}  // namespace aniso
