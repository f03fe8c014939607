#pragma once
// Surface curvature sizing that a spurious curvature cannot explode (sec. 2.4.2, alg. 3.2
// step 3, hardened; issue 20 "sizing that cannot explode").
//
// The point curvature of eq. 2.40 is only as good as the derivatives at that point. Next to
// a degenerate patch corner (collapsed control points: p_u = p_v = 0) or on a nearly flat
// patch whose control points carry noise it can be orders of magnitude above anything the
// surface does over the element size it asks for, and one such sample drives a whole face
// to h_min. The rule, for the lengths h_i of eq. 2.41 at a sample p (normal n):
//   1 secant check: a curvature is believed only as far as the surface bends over the
//     distance it asks for. For h = min h_i the surface is sampled at the 3D distance h from
//     p along kSecantLines parametric lines through p (the principal directions and their
//     bisectors), and the secant curvature of a line is
//         κ_s = 2 |n·(q₊ − p) + n·(q₋ − p)| / (|q₊ − p|² + |q₋ − p|²)
//     (one-sided, 2|n·(q − p)|/|q − p|², where a side has no room in the face's (u, v) box;
//     targets beyond the box are clamped into it, so corners keep their samples). It is
//     exactly 1/R on a circle of radius R (a cylinder, a fillet, a hole), and a tilt of n
//     cancels. With κ_s(h) the largest over the lines: while γ_c / κ_s(h) > (1 + kSecantSlack) h,
//     h ← min(γ_c / κ_s(h), h_max), at most kSecantSteps times (h only grows). A spike or a
//     ripple narrower than the size it asks for is bounded by what the surface deviates at
//     that size; a curvature real over its own size keeps its length.
//   2 floor: no length below RobustCurvatureBounds::floor (h_min, the CAD tolerance times
//     kToleranceFactor, and γ_c times the smallest radius of curvature believed on a face,
//     kMinRadiusFraction of the face's own width).
// Every h_i is raised to at least the result, then the anisotropy limit (eq. 2.42).
// Which rule does what (models/passage.step, a B-spline patch whose v = 0 row of control
// points is collapsed onto a corner, plus noise): the point curvature near the collapsed row
// is spurious (the fan the row makes is nearly flat), and the secant check removes it:
// without it the row asked for h_min and the control spaces did not finish
// (docs/measurements.md). The floor is a backstop (see the constants).
// Throws MeshingError as surfaceCurvatureSizing() does.
#include "mesher/geometry/ParametricSurface.h"
#include "mesher/metric/CurvatureSizing.h"
#include "mesher/metric/Metric.h"

namespace aniso {

/// Parametric lines sampled through a point: the two principal directions and their bisectors.
inline constexpr int kSecantLines = 4;
/// Bound of the secant iteration of step 1 (h grows at every step, so it ends anyway).
inline constexpr int kSecantSteps = 6;
/// h is kept when the secant curvature asks for at most this much more (5 %).
inline constexpr double kSecantSlack = 0.05;
/// No curvature length below this many times the face's CAD tolerance: geometry below the
/// tolerance is not defined, and a size within a few tolerances of it is noise.
inline constexpr double kToleranceFactor = 10.0;
/// No radius of curvature below this fraction of the face's width (its area / its extent),
/// i.e. no curvature length below γ_c · kMinRadiusFraction · width: the backstop for
/// curvature without bound (a singular point) when h_min is set far below the model's scale.
/// Real features come close: the thesis' SURF2 ridge has radii down to 3.7e-4 of its face's
/// width (a floor at 5e-3 cut most of its triangles: docs/measurements.md); fillets and holes
/// have radii of ~0.6 of their faces' widths.
inline constexpr double kMinRadiusFraction = 1e-3;

/// What the sampling and the floor of a face need to know.
struct RobustCurvatureBounds {
  Box2 uv;             ///< the face's (u, v) box: secant samples stay inside it
  double floor = 0;    ///< smallest curvature length (≥ h_min)

  /// max(h_min, kToleranceFactor · tolerance, γ_c · kMinRadiusFraction · faceWidth), ≤ h_max.
  static RobustCurvatureBounds of(const Box2& uv, const CurvatureSizing& sizing, double tolerance, double faceWidth);
};

/// The largest secant curvature κ_s at distance h from uv (step 1, the lines along `dirs`,
/// unit (u, v) directions; a sample's target is clamped into `box`) with the normal n at
/// uv; −1 when no sample could be placed (then the point curvature stands).
double secantCurvature(const ParametricSurface& surface, const Vec2& uv, const Vec3& n, const Vec2 (&dirs)[kSecantLines],
                       double h, const Box2& box);

/// M_s (in S^R) of the surface's curvature at uv by the rule above.
Metric2d robustCurvatureSizing(const ParametricSurface& surface, const Vec2& uv, double gMin,
                               const CurvatureSizing& sizing, const RobustCurvatureBounds& bounds);

}  // namespace aniso
