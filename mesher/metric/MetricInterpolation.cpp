#include "mesher/metric/MetricInterpolation.h"

#include <cmath>
#include <string>

#include "mesher/core/Error.h"
#include "mesher/metric/SymmetricEigen.h"

namespace aniso {

template <int D>
Metric<D> interpolate(const Metric<D>& m1, const Metric<D>& m2, double t) {
  if (!(t >= 0 && t <= 1))
    throw MeshingError("metric interpolation: parameter t = " + std::to_string(t) + " is outside [0, 1]");
  if (t == 0) return m1;
  if (t == 1) return m2;
  const typename Metric<D>::Mat inv = (1 - t) * m1.inverseMatrix() + t * m2.inverseMatrix();
  return Metric<D>::fromTransformation(symmetrize<D>(inv.inverse()));
}

template <int D>
void MetricBlend<D>::add(const Metric<D>& m, double weight) {
  if (!(std::isfinite(weight) && weight >= 0))
    throw MeshingError("metric interpolation: weight " + std::to_string(weight) + " is negative or not finite");
  if (weight == 0) return;
  sum_ += weight * m.inverseMatrix();
  weight_ += weight;
}

template <int D>
Metric<D> MetricBlend<D>::result() const {
  if (empty()) throw MeshingError("metric interpolation: no metric with positive weight");
  const Mat mean = sum_ / weight_;
  return Metric<D>::fromTransformation(symmetrize<D>(mean.inverse()));
}

template <int D>
Metric<D> interpolate(std::span<const Metric<D>> metrics, std::span<const double> weights) {
  if (metrics.size() != weights.size())
    throw MeshingError("metric interpolation: " + std::to_string(metrics.size()) + " metrics but " +
                       std::to_string(weights.size()) + " weights");
  MetricBlend<D> blend;
  for (std::size_t i = 0; i < metrics.size(); ++i) blend.add(metrics[i], weights[i]);
  return blend.result();
}

template Metric<2> interpolate(const Metric<2>&, const Metric<2>&, double);
template Metric<3> interpolate(const Metric<3>&, const Metric<3>&, double);
template class MetricBlend<2>;
template class MetricBlend<3>;
template Metric<2> interpolate(std::span<const Metric<2>>, std::span<const double>);
template Metric<3> interpolate(std::span<const Metric<3>>, std::span<const double>);

}  // namespace aniso
