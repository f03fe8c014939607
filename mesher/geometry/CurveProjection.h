#pragma once
// One-dimensional nearest-point search on a parameter interval: the getParameter of
// ParametricCurve2d/3d (sec. 6.2.2: bracketing, bisection and Newton).
#include <functional>

namespace aniso {

/// Squared-distance function g(t) = ½|c(t) − x|² and its first two derivatives
/// g' = (c − x)·c', g'' = |c'|² + (c − x)·c''.
struct DistanceSample {
  double g = 0, dg = 0, ddg = 0;
  /// |c − x|·|c'|, the size g' is measured against: |g'| ≤ 1e-12 × dgScale counts as
  /// stationary (the residual normal to the curve), which also keeps the start where the
  /// distance is constant (the centre of a circle).
  double dgScale = 0;
};

/// Parameter in [t0, t1] (either order) minimising g. The interval is sampled uniformly
/// (plus ts) to bracket every local minimum; each bracket is refined by a safeguarded
/// Newton iteration on g' (bisection when Newton leaves the bracket). The global minimum
/// is returned; between minima equal to round-off the one nearest to ts wins. Never throws;
/// non-finite or throwing samples are skipped.
double nearestParameter(const std::function<DistanceSample(double)>& eval, double ts, double t0,
                        double t1, int samples = 24);

}  // namespace aniso
