#include "mesher/metric/MetricComparison.h"

namespace aniso {

template <int D>
double metricDifference(const Metric<D>& m1, const Metric<D>& m2) {
  using Mat = typename Metric<D>::Mat;
  const Mat r1 = m1.inverseMatrix() * m2.matrix();
  const Mat r2 = m2.inverseMatrix() * m1.matrix();
  return (r1 + r2 - 2 * Mat::Identity()).norm();  // eq. 2.24–2.25
}

template double metricDifference(const Metric<2>&, const Metric<2>&);
template double metricDifference(const Metric<3>&, const Metric<3>&);

}  // namespace aniso
