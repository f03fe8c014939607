#pragma once
// Metric source: curvature of a surface patch (sec. 2.4.2, eq. 2.35–2.42).
//
// Input: the principal curvatures χ_1, χ_2 and directions y_1, y_2 at a point (from
// det(B − χG) = 0, eq. 2.40: ParametricSurface::curvature) and the parameterization
// tensor M_p at that point (eq. 2.8).
// Lengths: h_i = max(min(γ_c/|χ_i|, h_max), h_min) (eq. 2.41), then the anisotropy limit
// max h / min h ≤ γ_a (eq. 2.42, by shortening the longer length, AnisotropyLimit.h).
// Direction: y_1 is a direction of the parametric plane (u, v). The returned tensor is
// the sizing component M_s, which acts on S^R vectors (M_p x, see SurfaceMetric.h), so
// α_c is the angle of M_p y_1 in S^R — the angle of the principal direction measured on
// the surface from the image of the u base vector. (For an orthogonal parameterization,
// G diagonal, this equals the angle of y_1 in (u, v).) M_p y_1 ⟂ M_p y_2 because the
// principal directions are G-orthogonal, so (α_c, h_1, h_2) → eq. 2.4 is exact.
//
// Output: M_s in S^R. The caller forms the full transformation M = M_s M_p (eq. 2.9,
// surfaceTransformation()) to measure parametric vectors; with it, a parametric vector x
// along y_i with surface length |Dp x| = h_i has metric length 1.
// Throws MeshingError for non-finite curvature, a singular M_p or invalid parameters.
#include "mesher/geometry/ParametricSurface.h"
#include "mesher/metric/CurvatureSizing.h"
#include "mesher/metric/Metric.h"

namespace aniso {

/// M_s (in S^R) from principal curvatures and the parameterization tensor at the point.
Metric2d surfaceCurvatureSizing(const PrincipalCurvatures& pc, const Mat2& mp,
                                const CurvatureSizing& sizing);

/// M_s with the lengths h = (h_1, h_2) along pc's principal directions, after the
/// anisotropy limit γ_a (eq. 2.42, 2.4): the assembly step of the function above.
Metric2d principalSizing(const PrincipalCurvatures& pc, const Mat2& mp, Vec2 h, double anisotropy);

/// Convenience: curvature() and parameterizationTensor(uv, gMin) of the surface at uv.
Metric2d surfaceCurvatureSizing(const ParametricSurface& surface, const Vec2& uv, double gMin,
                                const CurvatureSizing& sizing);

}  // namespace aniso
