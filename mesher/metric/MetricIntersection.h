#pragma once
// Metric intersection min_M (sec. 2.3.2, eq. 2.19–2.23): the metric whose unit ellipse
// (ellipsoid) is the largest one contained in the unit ellipses of all inputs, i.e. it
// requests, in every direction, at most the lengths requested by each input.
//
// Phases (as in the thesis): (1) transformation tensors to metric tensors 𝓜 = M Mᵀ
// (2.19); (2) simultaneous reduction of 𝓜1, 𝓜2: the eigenvectors e_i of 𝓝 = 𝓜1⁻¹𝓜2
// (2.20), the Rayleigh quotients λ_ki = e_iᵀ 𝓜k e_i (2.21) and
// 𝓜_min = A⁻ᵀ diag(max(λ_1i, λ_2i)) A⁻¹ with A = [e_1 … e_d] (2.22 — the thesis prints
// A⁻¹ … A⁻¹; the transpose is needed for a symmetric result); (3) back to the symmetric
// transformation tensor R diag(√λ_i) Rᵀ (2.23).
// Implementation of phase 2: with the Cholesky factor 𝓜1 = L Lᵀ, C = L⁻¹ 𝓜2 L⁻ᵀ = Q Λ Qᵀ
// gives the 𝓜1-orthonormal e_i = L⁻ᵀ q_i, so λ_1i = 1, λ_2i = Λ_i and
// 𝓜_min = L Q diag(max(1, Λ_i)) Qᵀ Lᵀ. More than two metrics: all are converted to
// tensors, intersected one by one, converted back once (sec. 2.3.2).
//
// Guarantees: for every vector v, |M_min v| ≥ |M_k v| (containment: the result's unit
// ellipse lies inside each input's). Touching: when neither input ellipse contains the
// other, the result touches both (equality along a common eigenvector); when one lies
// inside the other, the result is that inner input (returned exactly, see `tol`), which
// then touches only itself. The operation is commutative up to round-off. For surfaces only sizing components M_s are
// intersected (sec. 2.3.2). No heap allocation; throws MeshingError if round-off makes a
// result non-SPD (only for absurdly ill-conditioned input).
#include <span>

#include "mesher/metric/Metric.h"

namespace aniso {

/// Relative tolerance of "unchanged": all Λ_i ≤ 1 + tol.
inline constexpr double kIntersectionTolerance = 1e-12;

/// Phase 2 on metric tensors (SPD). When every Λ_i ≤ 1 + tol the result is t1 itself and
/// *firstChanged (if given) is false; when every Λ_i ≥ 1 − tol it is t2 itself.
template <int D>
Eigen::Matrix<double, D, D> intersectTensors(const Eigen::Matrix<double, D, D>& t1,
                                             const Eigen::Matrix<double, D, D>& t2,
                                             bool* firstChanged = nullptr,
                                             double tol = kIntersectionTolerance);

/// min_M(a, b) (eq. 2.23).
template <int D>
Metric<D> intersect(const Metric<D>& a, const Metric<D>& b);

/// a ← min_M(a, b); returns whether a changed (some Λ_i > 1 + tol). When it returns false
/// a is untouched.
template <int D>
bool intersectInto(Metric<D>& a, const Metric<D>& b, double tol = kIntersectionTolerance);

/// min_M of all metrics (at least one).
template <int D>
Metric<D> intersect(std::span<const Metric<D>> metrics);

inline Metric2d intersect(std::span<const Metric2d> metrics) { return intersect<2>(metrics); }
inline Metric3d intersect(std::span<const Metric3d> metrics) { return intersect<3>(metrics); }

}  // namespace aniso
