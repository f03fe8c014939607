#include "mesher/metric/AnisotropyLimit.h"

#include <cmath>
#include <string>

#include "mesher/core/Error.h"

namespace aniso {

template <int D>
bool limitLengthRatio(Eigen::Matrix<double, D, 1>& lengths, double gammaA) {
  if (!(std::isfinite(gammaA) && gammaA >= 1))
    throw MeshingError("anisotropy limit: gamma_a = " + std::to_string(gammaA) + " must be finite and >= 1");
  const double cap = gammaA * lengths.minCoeff();
  bool changed = false;
  for (int i = 0; i < D; ++i) {
    if (lengths(i) > cap) {
      lengths(i) = cap;
      changed = true;
    }
  }
  return changed;
}

template <int D>
Metric<D> limitAnisotropy(const Metric<D>& m, double gammaA) {
  MetricAxes<D> a = m.axes();
  if (!limitLengthRatio<D>(a.lengths, gammaA)) return m;
  return Metric<D>::fromAxes(a.directions, a.lengths);
}

template <int D>
double anisotropyRatio(const Metric<D>& m) {
  const MetricAxes<D> a = m.axes();
  return a.lengths.maxCoeff() / a.lengths.minCoeff();
}

template bool limitLengthRatio<2>(Eigen::Matrix<double, 2, 1>&, double);
template bool limitLengthRatio<3>(Eigen::Matrix<double, 3, 1>&, double);
template Metric<2> limitAnisotropy(const Metric<2>&, double);
template Metric<3> limitAnisotropy(const Metric<3>&, double);
template double anisotropyRatio(const Metric<2>&);
template double anisotropyRatio(const Metric<3>&);

}  // namespace aniso
