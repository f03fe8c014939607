#pragma once
// Metric of a simplex (sec. 2.4.1, eq. 2.33–2.34): the unique metric tensor 𝓜_K for which
// every edge of the non-degenerate simplex K has unit length,
//   (P_j − P_i)ᵀ 𝓜_K (P_j − P_i) = 1,   1 ≤ i < j ≤ d + 1,
// i.e. the metric in which K is the equilateral simplex with unit edges.
//
// Computed in closed form instead of solving the d(d+1)/2 linear system 2.34: with the
// edge matrix J = [P_2 − P_1, …, P_{d+1} − P_1] and the Gram matrix G_ref of the unit
// equilateral simplex (1 on the diagonal, ½ elsewhere), the affine map x ↦ E J⁻¹ x sends K
// to the reference simplex, so 𝓜_K = J⁻ᵀ G_ref J⁻¹ (symmetric positive definite; the same
// unique solution). The orientation of K does not matter.
// The transformation tensor M_K = 𝓜_K^{1/2} (sec. 2.3.2). For a triangle in the
// parametric plane of a surface M_K contains both the sizing and the parameterization
// components (see NonConformity.h for separating them).
//
// Throws MeshingError for non-finite coordinates or a degenerate simplex: |det J| at most
// kDegenerateSimplex · (longest edge)^d.
#include "mesher/metric/Metric.h"

namespace aniso {

/// Relative size of |det J| below which a simplex counts as degenerate.
inline constexpr double kDegenerateSimplex = 1e-12;

/// 𝓜_K of a triangle (eq. 2.34).
Mat2 simplexMetricTensor(const Vec2& p1, const Vec2& p2, const Vec2& p3);
/// 𝓜_K of a tetrahedron (eq. 2.33, d = 3).
Mat3 simplexMetricTensor(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4);

/// M_K = 𝓜_K^{1/2}.
Metric2d simplexMetric(const Vec2& p1, const Vec2& p2, const Vec2& p3);
Metric3d simplexMetric(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4);

}  // namespace aniso
