#pragma once
// Metric gradation smoothing between two points (sec. 2.3.4, eq. 2.26–2.32).
//
// γ_M (≥ 1) limits the increase of the requested edge length, in any direction, between
// two points a unit metric distance apart (1D: γ_M = h_{i+1}/h_i). For points P1, P2 with
// sizing tensors M_s1, M_s2 and the vector d = P2^R − P1^R between them in the space the
// tensors act on (S^R for surfaces: d = M_p (P2 − P1) with M_p at the midpoint, eq. 2.13
// and 2.14; physical space in 3D):
//
//   h_1, h_2  requested lengths along d in M_s1, M_s2; h_min, h_max their min and max
//   a      = (h_max − h_min) / d_R                          (2.26), d_R = |d|
//   a_max  = 2 (γ_M − 1) / (γ_M + 1)                        (2.27)
//   if a > a_max: a ← a_max, h_max ← a d_R + h_min          (2.28, 2.29)
//   s      = 1 − (1 − γ_M)(1 − a/2) d_R / h_min             (2.30)
//   M'_s1  = min_M(M_s1, "s M_s2"),  M'_s2 = min_M(M_s2, "s M_s1")   (2.31, 2.32)
//
// Interpretation (documented choice): s ≥ 1 is a factor on *lengths* — "s M" in 2.31–2.32
// is the metric requesting s times the lengths of M, i.e. the tensor M / s. Multiplying the
// tensor by s ≥ 1 would request shorter lengths than either input, and repeated smoothing
// would refine without end. With a = a_max, s = 1 + a_max d_R / h_min is exactly the growth
// of a linear size field of the largest admissible slope (the derivation of 2.27). The
// updated h_max of 2.29 does not enter s; it is not needed.
// Both updates use the metrics as they were on entry (simultaneous update).
//
// Guarantees after a call: for every direction u, h_1(u) ≤ s h_2(u) and h_2(u) ≤ s h_1(u)
// for the s of this call; since 0 ≤ a ≤ a_max < 2, 1 ≤ s ≤ 1 + (γ_M − 1) d_R / h_min, so at
// a unit metric distance the length ratio in any direction is at most γ_M. Metrics only
// ever become finer. Iterating over all neighbour pairs until no call reports a change
// yields a field where every pair satisfies the bound for its own (final) s.
#include "mesher/metric/Metric.h"

namespace aniso {

struct GradationRule {
  double gamma = 4.0;           ///< γ_M ≥ 1 (SizingParameters::gradation)
  double skipDifference = 0.0;  ///< ε_δ: skip pairs with δ_M(M_s1, M_s2) < ε_δ; 0 never skips
  double changeTolerance = 1e-9;  ///< relative eigenvalue change that counts as a change
};

/// a_max of eq. 2.27. Throws MeshingError unless γ is finite and ≥ 1.
double gradationSlopeLimit(double gamma);

/// The length factor s of eq. 2.26–2.30 for lengths hA, hB (> 0) requested along a
/// segment of length dR ≥ 0 in the tensors' space. dR = 0 gives s = 1.
double gradationFactor(double hA, double hB, double dR, double gamma);

/// Eq. 2.31–2.32 applied to m1 (at P1) and m2 (at P2), d = P2^R − P1^R. Returns whether
/// either metric changed. Throws MeshingError on an invalid rule or non-finite d.
template <int D>
bool smoothGradation(Metric<D>& m1, Metric<D>& m2, const Eigen::Matrix<double, D, 1>& d,
                     const GradationRule& rule);

}  // namespace aniso
