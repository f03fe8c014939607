#include "mesher/metric/MetricGradation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesher/core/Error.h"
#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricIntersection.h"

namespace aniso {

double gradationSlopeLimit(double gamma) {
  if (!(std::isfinite(gamma) && gamma >= 1))
    throw MeshingError("metric gradation: gamma_M = " + std::to_string(gamma) + " must be finite and >= 1");
  return 2 * (gamma - 1) / (gamma + 1);  // eq. 2.27
}

double gradationFactor(double hA, double hB, double dR, double gamma) {
  const double aMax = gradationSlopeLimit(gamma);
  if (!(std::isfinite(hA) && hA > 0 && std::isfinite(hB) && hB > 0 && std::isfinite(dR) && dR >= 0))
    throw MeshingError("metric gradation: lengths must be positive and the distance finite");
  if (dR == 0) return 1;
  const double hMin = std::min(hA, hB), hMax = std::max(hA, hB);
  double a = (hMax - hMin) / dR;  // eq. 2.26
  if (a > aMax) a = aMax;         // eq. 2.28 (2.29 only updates h_max, unused by s)
  return 1 - (1 - gamma) * (1 - a / 2) * dR / hMin;  // eq. 2.30
}

template <int D>
bool smoothGradation(Metric<D>& m1, Metric<D>& m2, const Eigen::Matrix<double, D, 1>& d,
                     const GradationRule& rule) {
  gradationSlopeLimit(rule.gamma);
  if (!d.allFinite()) throw MeshingError("metric gradation: the segment vector is not finite");
  if (rule.skipDifference > 0 && metricDifference(m1, m2) < rule.skipDifference) return false;
  const double dR = d.norm();
  const double s = dR > 0 ? gradationFactor(m1.lengthAlong(d), m2.lengthAlong(d), dR, rule.gamma) : 1.0;
  // "s M" = the metric of s times longer lengths = tensor M / s (see the header).
  const Metric<D> relaxed1 = m1.scaled(1 / s);
  const Metric<D> relaxed2 = m2.scaled(1 / s);
  const bool c1 = intersectInto(m1, relaxed2, rule.changeTolerance);  // eq. 2.31
  const bool c2 = intersectInto(m2, relaxed1, rule.changeTolerance);  // eq. 2.32
  return c1 || c2;
}

template bool smoothGradation(Metric<2>&, Metric<2>&, const Eigen::Matrix<double, 2, 1>&, const GradationRule&);
template bool smoothGradation(Metric<3>&, Metric<3>&, const Eigen::Matrix<double, 3, 1>&, const GradationRule&);

}  // namespace aniso
