#pragma once
// Metric length of a segment / edge (eq. 2.11, 2.14, the integral of sec. 2.2 and the
// metric edge length μ_M of sec. 2.5.2, eq. 2.49).
//
// A "transform" is either a Metric<D> (symmetric M) or a plain D×D matrix (the surface
// transformation M = M_s M_p). A "field" is any callable returning a transform for a
// point (e.g. a control space lookup).
//   metricLength(M, a, b)          |M (b − a)|, M constant along ab (eq. 2.11).
//   metricLengthMidpoint(f, a, b)  M taken at the midpoint (eq. 2.14).
//   metricLengthGauss(f, a, b)     ∫₀¹ |M(a + t(b − a)) (b − a)| dt by 3-point
//                                  Gauss–Legendre (the variable-metric length of sec. 2.2).
// The edge length of a unit mesh is 1; the mean over the edges of a mesh is μ̄_M (2.49),
// accumulate it with QualityStats. Header-only, no allocation, no checks.
#include <cmath>
#include <type_traits>

#include "mesher/metric/Metric.h"

namespace aniso {

template <int D>
inline double metricLength(const Metric<D>& m, const Eigen::Matrix<double, D, 1>& a,
                           const Eigen::Matrix<double, D, 1>& b) {
  return m.length(b - a);
}

template <int D>
inline double metricLength(const Eigen::Matrix<double, D, D>& m,
                           const Eigen::Matrix<double, D, 1>& a,
                           const Eigen::Matrix<double, D, 1>& b) {
  return (m * (b - a)).norm();
}

template <class Field, int D>
inline double metricLengthMidpoint(const Field& field, const Eigen::Matrix<double, D, 1>& a,
                                   const Eigen::Matrix<double, D, 1>& b) {
  const Eigen::Matrix<double, D, 1> mid = 0.5 * (a + b);
  return metricLength<D>(field(mid), a, b);
}

template <class Field, int D>
inline double metricLengthGauss(const Field& field, const Eigen::Matrix<double, D, 1>& a,
                                const Eigen::Matrix<double, D, 1>& b) {
  // Gauss–Legendre on [0, 1]: nodes ½ ± ½√(3/5) and ½, weights 5/18, 5/18, 8/18.
  const double off = 0.5 * std::sqrt(0.6);
  const double nodes[3] = {0.5 - off, 0.5, 0.5 + off};
  const double weights[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  const Eigen::Matrix<double, D, 1> v = b - a;
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Matrix<double, D, 1> p = a + nodes[i] * v;
    sum += weights[i] * metricLength<D>(field(p), Eigen::Matrix<double, D, 1>::Zero(), v);
  }
  return sum;
}

}  // namespace aniso
