#pragma once
// Metric source: curvature of a contour curve (sec. 2.4.3, eq. 2.43–2.46).
//
// Input: the curvature κ of the 3D contour c = p ∘ c_p (eq. 2.45,
// ParametricCurve2d::curvature), the tangent c_p' in the parametric plane and the
// parameterization tensor M_p at the point.
// Lengths (eq. 2.46): h_1 = max(min(γ_c/κ, h_max), h_min) along the contour tangent and
// h_2 = γ_ac h_1 across it (γ_ac ≤ γ_a keeps elements along strongly curved contours
// only mildly stretched). Interpretation: h_2 is also capped at h_max (the thesis applies
// the bound to h_1 only; h_max is the largest edge length of the mesh, so a straight
// contour gives the isotropic h_max instead of γ_ac h_max).
// Direction: α_c is the angle of the tangent measured on the surface, i.e. of M_p c_p' in
// S^R (as in SurfaceCurvatureMetric.h; for an orthogonal parameterization it is the angle
// between the u base vector and c_p').
//
// Output: the sizing component M_s in S^R; the caller forms M = M_s M_p (eq. 2.9).
// Throws MeshingError for a zero or non-finite tangent, non-finite κ, a singular M_p or
// invalid parameters.
#include "mesher/geometry/ParametricCurve2d.h"
#include "mesher/geometry/ParametricSurface.h"
#include "mesher/metric/CurvatureSizing.h"
#include "mesher/metric/Metric.h"

namespace aniso {

/// M_s (in S^R) from the contour curvature and its parametric tangent.
Metric2d contourCurvatureSizing(double kappa, const Vec2& tangentUV, const Mat2& mp,
                                const CurvatureSizing& sizing);

/// Convenience: κ, c_p(t), c_p'(t) from the curve and M_p = parameterizationTensor(c_p(t), gMin).
Metric2d contourCurvatureSizing(const ParametricCurve2d& curve, double t,
                                const ParametricSurface& surface, double gMin,
                                const CurvatureSizing& sizing);

}  // namespace aniso
