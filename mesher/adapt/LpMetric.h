#pragma once
// lpMetric — the metric that minimises the Lp norm of the P1 interpolation error of a
// field for a given number of nodes (Loseille & Alauzet, "Continuous mesh framework",
// Part I sec. 5 and Part II sec. 2, SIAM J. Numer. Anal. 2011), from its recovered
// Hessians H (HessianRecovery.h):
//   M_Lp(x) = D · det|H(x)|^(−1/(2p+d)) · |H(x)|
// with |H| the absolute values of H's eigenvalues (floored at kHessianFloor times the
// largest over the mesh, so that a node of a locally linear field gets the coarsest size),
// then, in M's eigen-basis, every eigenvalue clamped to [1/hmax², 1/hmin²] and raised to
// at least λ_max/γ_a² (the anisotropy limit, eq. 3.3's form). D is found by bisection so
// that either
//   the predicted node count a_d · C(D) + b_d · C_∂(D) matches targetNodes, with
//   C(D) = ∫ √det M (the complexity: over the nodes, √det M times their lumped measure)
//   and C_∂(D) = ∫_∂ √det M|_∂ (the boundary's: over the boundary facets, the mean of
//   their nodes' √det of M restricted to the facet, times its area / length) — the
//   surface nodes the mesher puts on the boundary come on top of the interior's; or
//   the predicted Lp error (∫ e^p)^(1/p), e = c_d · trace(M^(−1/2) |H| M^(−1/2)) (the
//   continuous interpolation error, c_2 = 1/8, c_3 = 1/10; Part I sec. 4), matches error.
// The clamps make the prediction the count / error of the clamped metric. When the asked
// value lies outside what hmin and hmax allow, the nearest end is taken (`limited` says so).
// dim 3: nodes of a tet mesh; dim 2: nodes of a surface, H and M in the tangent plane
// (normal: `normals`), M's size along the normal is hmax.
// Throws MeshingError for parameters out of range (p < 1, hmin ≤ 0, hmax < hmin, γ_a < 1,
// neither or both of targetNodes and error) and for a field whose Hessian is zero
// everywhere (a linear field asks for no adaptation).
#include <vector>

#include "mesher/adapt/PatchMesh.h"
#include "mesher/metric/Metric.h"

namespace aniso {

inline constexpr double kHessianFloor = 1e-12;
/// a_d, b_d above: nodes per unit of interior and of boundary complexity, measured on
/// meshes of a uniform metric (the Hessian of |x|²) by `anisomesh adapt`, whose volume
/// metric is kVolumeLengthFactor finer than its tets (AdaptSources.h): 3D fitted on a cube,
/// 2D a_2 = 2/√3 and b_2 from the unit square (docs/measurements.md). For comparison, a
/// regular unit tet has volume √2/12 and a Delaunay mesh ~6 tets per node (1.4 nodes per unit
/// volume), a unit equilateral triangle area √3/4 and a triangle mesh 2 per node (1.15 per
/// unit area).
inline constexpr double kInteriorNodesPerComplexity[4] = {0, 0, 1.1547, 1.659};
inline constexpr double kBoundaryNodesPerComplexity[4] = {0, 0, 0.55, 2.657};

struct LpMetricParameters {
  int dim = 3;
  double norm = 2;         ///< p ≥ 1
  double targetNodes = 0;  ///< > 0: scale to this node count
  double error = 0;        ///< > 0: scale to this Lp error (field units × measure^(1/p))
  double hmin = 0, hmax = 0;
  double anisotropy = 10;  ///< γ_a ≥ 1
};

struct LpMetric {
  std::vector<Metric3d> metrics;  ///< one per node
  double predictedNodes = 0;
  double predictedError = 0;
  bool limited = false;  ///< the target was out of reach within [hmin, hmax]
};

/// `hessians`, `measures` (nodeMeasures) and, for dim 2, `normals` have one entry per node;
/// `boundary` (boundaryFacets) may be empty (no boundary term).
LpMetric lpMetric(const std::vector<Mat3>& hessians, const std::vector<double>& measures,
                  const std::vector<Vec3>& normals, const std::vector<BoundaryFacet>& boundary,
                  const LpMetricParameters& params);

}  // namespace aniso
