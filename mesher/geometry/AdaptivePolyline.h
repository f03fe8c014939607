#pragma once
// Adaptive polyline approximation of a parametrised point map t → P(t) ∈ R³: the
// getPolyline of ParametricCurve2d/3d (sec. 6.2.2). A 2D curve passes its points with
// z = 0, or their images on its surface.
#include <functional>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

/// Parameters t0 = s_0, s_1, ..., s_n = t1 (monotone, n ≥ 1, t1 < t0 allowed) such that on
/// each piece the deviation of P at its 1/4, 1/2 and 3/4 parameters from the chord is at
/// most tol × chord length. Pieces are bisected; a piece is accepted anyway when its
/// parameter length reaches round-off level or after maxDepth bisections. The first
/// subdivision is uniform in `initial` pieces so that closed curves (P(t0) = P(t1)) work.
std::vector<double> adaptivePolyline(const std::function<Vec3(double)>& point, double t0,
                                     double t1, double tol, int initial = 4, int maxDepth = 40);

}  // namespace aniso
