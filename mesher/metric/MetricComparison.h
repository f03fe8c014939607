#pragma once
// Metric comparison δ_M (sec. 2.3.3, eq. 2.24–2.25): with the residuals
//   R1 = M1⁻¹ M2 − I,   R2 = M2⁻¹ M1 − I,
// δ_M(M1, M2) = ‖R1 + R2‖, the Euclidean (Frobenius) matrix norm.
//
// Guarantees: δ_M(M, M) = 0 (up to round-off), δ_M(M1, M2) = δ_M(M2, M1) exactly (the sum
// is formed symmetrically), δ_M ≥ 0, scale-aware: δ_M(M, sM) = √d |s + 1/s − 2|, so the
// difference between an isotropic h and h' grows with both h/h' and h'/h. Works for any
// pair of tensors from the same space (for surfaces: sizing components M_s, sec. 2.5.3).
// Also used as the non-conformity coefficient E_K (NonConformity.h). No allocation.
#include "mesher/metric/Metric.h"

namespace aniso {

template <int D>
double metricDifference(const Metric<D>& m1, const Metric<D>& m2);

}  // namespace aniso
