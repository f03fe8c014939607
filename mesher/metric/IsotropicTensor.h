#pragma once
// The isotropy test shared by the per-vertex metric stores of the volume mesher
// (refine/VertexTensors, improve/VertexMetrics) and the refinement's in-sphere fast path:
// a transformation tensor M is isotropic when M = s·I up to a relative tolerance.
#include "mesher/core/Types.h"

namespace aniso {

/// Relative off-isotropy (|M − s·I| / s, Frobenius) below which a tensor counts as s·I.
inline constexpr double kIsotropicTolerance = 1e-12;

/// s = trace(M)/3 when M is s·I up to kIsotropicTolerance and s > 0, else 0.
inline double isotropicScale(const Mat3& m) {
  const double s = m.trace() / 3;
  return s > 0 && (m - s * Mat3::Identity()).norm() <= kIsotropicTolerance * s ? s : 0;
}

}  // namespace aniso
