#pragma once
// Choosing the representative of a periodic parameter nearest to a reference value: the
// "left unwrapped near start" rule of the projections (ParametricSurface::project).
#include <cmath>

namespace aniso {

/// The value a + k·period (k integer) nearest to ref. Returns a when period <= 0 or a
/// value is not finite.
inline double nearestPeriodic(double a, double ref, double period) {
  if (!(period > 0) || !std::isfinite(a) || !std::isfinite(ref)) return a;
  return a + period * std::round((ref - a) / period);
}

}  // namespace aniso
