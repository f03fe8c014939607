#pragma once
// Adaptive Gauss–Kronrod (7/15 point) quadrature of a scalar function on [a, b]: the
// integration behind the curve lengths of ParametricCurve2d/3d (sec. 6.2.2, getLength).
#include <functional>

namespace aniso {

/// ∫_a^b f(t) dt (signed: negative when b < a). Intervals are bisected until the
/// Kronrod–Gauss difference on each is below its share of relTol × |integral estimate|
/// (plus a tiny absolute floor), to a bisection depth of at most maxDepth.
double integrateAdaptive(const std::function<double(double)>& f, double a, double b,
                         double relTol = 1e-10, int maxDepth = 30);

}  // namespace aniso
