#pragma once
// recoverHessian — the Hessian of a nodal field at every node of a PatchMesh (issue 19, the
// first step of a metric from a solution; Loseille & Alauzet 2011, sec. 4):
//   LeastSquares  a quadratic fitted by least squares to the values of the node's patch
//                 (the nodes sharing a cell with it; 2 rings at boundary nodes, where one
//                 ring is one-sided, and wherever one ring has fewer than kMinPatchExtra
//                 nodes beyond the quadratic's unknowns or leaves the fit rank-deficient;
//                 at most kMaxPatchRings rings). Exact for quadratics at every node.
//   DoubleL2      the gradient of the P1 interpolant (corners only) per cell, averaged to
//                 the nodes by cell measure, and again for each gradient component. Not
//                 exact at boundary nodes or on irregular meshes; kept for comparison
//                 (tests/unit/adapt_hessian_test.cpp measures both: least squares is the
//                 default).
// dim 3: the full 3×3 Hessian. dim 2 (a surface in space): the quadratic is fitted in the
// node's tangent plane (nodeNormals) and returned as T H₂ Tᵀ (zero along the normal).
// A node whose patch cannot carry a fit (an isolated node, a zero normal) gets zero.
// Deterministic; no exceptions for degenerate input (zero Hessians instead).
#include <vector>

#include "mesher/adapt/PatchMesh.h"

namespace aniso {

enum class HessianMethod { LeastSquares, DoubleL2 };

/// Extra nodes a patch must have beyond the unknowns of the fit (10 in 3D, 6 on a surface).
inline constexpr int kMinPatchExtra = 3;
/// The largest patch: this many rings of neighbours.
inline constexpr int kMaxPatchRings = 3;

/// `f` has one value per node of `m`.
std::vector<Mat3> recoverHessian(const PatchMesh& m, const std::vector<double>& f,
                                 HessianMethod method = HessianMethod::LeastSquares);

}  // namespace aniso
