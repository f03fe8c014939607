#pragma once
// Metric non-conformity coefficient E_K (sec. 2.5.3, eq. 2.50–2.51):
//   E_K = δ_M(M_K, M(K)),
// the metric difference (MetricComparison.h) between the metric M_K of the simplex
// (SimplexMetric.h: the metric in which K is equilateral with unit edges) and the metric
// M(K) prescribed for it (the control space at a representative point). E_K = 0 exactly
// when K is a perfect unit element of M(K); the mesh value Ē_K (2.51) is the mean over
// elements: QualityStats.
//
// Surface triangles (vertices in the parametric plane): only the sizing parts are
// compared (sec. 2.5.3). The decomposition of M_K into M_sK and M_pK is done by mapping
// the vertices to S^R with the element's parameterization tensor M_p (eq. 2.12) and taking
// the simplex metric there: that is M_sK, which is compared with the prescribed M_s(K).
// Throws MeshingError for a degenerate simplex (no simplex metric exists).
#include "mesher/metric/Metric.h"

namespace aniso {

/// E_K of a triangle in the plane (or in S^R) against the prescribed metric.
double nonConformity(const Metric2d& prescribed, const Vec2& p1, const Vec2& p2, const Vec2& p3);
/// E_K of a parametric-plane triangle: sizing compared in S^R (M_p of the element).
double nonConformitySurface(const Metric2d& prescribedSizing, const Mat2& mp, const Vec2& p1,
                            const Vec2& p2, const Vec2& p3);
/// E_K of a tetrahedron.
double nonConformity(const Metric3d& prescribed, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                     const Vec3& p4);

}  // namespace aniso
