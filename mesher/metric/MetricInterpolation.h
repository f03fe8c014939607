#pragma once
// Metric interpolation (sec. 2.3.1, eq. 2.18): linear interpolation of the inverse
// transformation tensors M⁻¹ = R diag(h_i) Rᵀ (the "length tensors"), then inversion:
//
//   M(Q) = ((1 − t) M⁻¹(P1) + t M⁻¹(P2))⁻¹,   Q = P1 + t (P2 − P1), t ∈ [0, 1].
//
// The n-point generalisation used by control spaces (weighted averages of control
// vertices, sec. 3.3.1) is M = (Σ w_i M_i⁻¹ / Σ w_i)⁻¹, w_i ≥ 0, Σ w_i > 0.
//
// Guarantees: the result is a valid Metric (a convex combination of SPD matrices is SPD);
// interpolating a metric with itself returns that metric (up to round-off); with t = 0
// (t = 1) the first (second) input is returned exactly. Works in any space as long as all
// inputs live in the same one (for surfaces: the sizing components M_s, sec. 2.3.1).
// Throws MeshingError for t outside [0, 1], negative or non-finite weights, zero total
// weight, or mismatched span sizes. No heap allocation.
#include <span>

#include "mesher/metric/Metric.h"

namespace aniso {

/// Eq. 2.18.
template <int D>
Metric<D> interpolate(const Metric<D>& m1, const Metric<D>& m2, double t);

/// Accumulator of the weighted n-point interpolation: add(metric, weight) any number of
/// times, then result(). Weight 0 contributions are ignored.
template <int D>
class MetricBlend {
 public:
  using Mat = typename Metric<D>::Mat;
  void add(const Metric<D>& m, double weight);
  /// Total weight so far.
  double weight() const { return weight_; }
  bool empty() const { return !(weight_ > 0); }
  /// (Σ w_i M_i⁻¹ / Σ w_i)⁻¹. Throws MeshingError when nothing was added.
  Metric<D> result() const;

 private:
  Mat sum_ = Mat::Zero();
  double weight_ = 0;
};

/// Weighted n-point interpolation; metrics.size() == weights.size() > 0.
template <int D>
Metric<D> interpolate(std::span<const Metric<D>> metrics, std::span<const double> weights);

/// Non-template entry points so that containers convert to spans implicitly.
inline Metric2d interpolate(std::span<const Metric2d> metrics, std::span<const double> weights) {
  return interpolate<2>(metrics, weights);
}
inline Metric3d interpolate(std::span<const Metric3d> metrics, std::span<const double> weights) {
  return interpolate<3>(metrics, weights);
}

}  // namespace aniso
