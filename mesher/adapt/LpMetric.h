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
//   the predicted node count kNodesPerComplexity[d] · C(D), C(D) = ∫ √det M (the
//   complexity, a sum over the nodes of √det M times their lumped measure), matches
//   targetNodes; or
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

#include "mesher/metric/Metric.h"

namespace aniso {

inline constexpr double kHessianFloor = 1e-12;
/// Nodes per unit of complexity. 2D: a unit equilateral triangle has area √3/4 and a
/// triangle mesh two triangles per node, so 2/√3. 3D: a regular unit tet has volume
/// √2/12 and a Delaunay tet mesh about 6.3 tets per node: 1.35 (calibrated in the adapt CLI
/// test on the cube, where the measured count is within ±30 % of the target).
inline constexpr double kNodesPerComplexity[4] = {0, 0, 1.1547, 1.35};

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

/// `hessians`, `measures` (nodeMeasures) and, for dim 2, `normals` have one entry per node.
LpMetric lpMetric(const std::vector<Mat3>& hessians, const std::vector<double>& measures,
                  const std::vector<Vec3>& normals, const LpMetricParameters& params);

}  // namespace aniso
