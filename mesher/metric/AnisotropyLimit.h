#pragma once
// Anisotropy limit γ_a (sec. 2.4.2, eq. 2.42): max(h_i) / min(h_i) ≤ γ_a.
//
// The limit is enforced by shortening the longer lengths, h_i ← min(h_i, γ_a · min_j h_j):
// the smallest requested length (the one a curvature or user source actually demands) is
// kept, the main directions are kept, and the result is never coarser than the input in
// any direction (its unit ellipse is contained in the input's).
// Throws MeshingError when γ_a is not finite or < 1.
#include "mesher/metric/Metric.h"

namespace aniso {

/// Clamp the ratio of lengths (any order) in place; returns whether a length changed.
template <int D>
bool limitLengthRatio(Eigen::Matrix<double, D, 1>& lengths, double gammaA);

/// The metric with the same directions and smallest length and ratio ≤ γ_a.
template <int D>
Metric<D> limitAnisotropy(const Metric<D>& m, double gammaA);

/// max(h_i) / min(h_i) of a metric.
template <int D>
double anisotropyRatio(const Metric<D>& m);

}  // namespace aniso
