#pragma once
// The surface transformation tensor and the spaces of surface meshing (sec. 2.2.1).
//
// Spaces, for a surface patch p : S → R³ meshed in its parametric plane S:
//   S    the parametric plane (u, v); mesh vertices live here.
//   S^R  = M_p S (eq. 2.12): parametric vectors multiplied by the parameterization tensor
//        M_p = G^{1/2} (eq. 2.8, ParametricSurface::parameterizationTensor). Since
//        |M_p x| = |Dp x|, S^R is locally an isometric copy of the tangent plane: distances
//        in S^R are distances on the surface (eq. 2.13).
//   S^M  = M S (eq. 2.10) with M = M_s M_p (eq. 2.9): metric space, where the requested
//        mesh is a unit mesh (eq. 2.11).
// The sizing component M_s (a Metric2d) therefore acts on S^R vectors; its directions
// and lengths are directions and lengths on the surface. M is not symmetric in general
// and is kept as a plain Mat2. For a metric field varying along a segment, M is taken at
// the midpoint (eq. 2.14, MetricLength.h).
// All functions are inline and allocation-free; only sizingComponent() and
// angleInRealSpace() check their input.
#include <cmath>

#include "mesher/core/Error.h"
#include "mesher/metric/Metric.h"

namespace aniso {

/// M = M_s M_p (eq. 2.9).
inline Mat2 surfaceTransformation(const Metric2d& sizing, const Mat2& mp) {
  return sizing.matrix() * mp;
}

/// The sizing component of a surface transformation M = M_s M_p: M_s = M M_p⁻¹ as a
/// Metric2d (throws MeshingError when the result is not symmetric positive definite, i.e.
/// M did not come from a symmetric sizing tensor and this M_p).
inline Metric2d sizingComponent(const Mat2& m, const Mat2& mp) {
  return Metric2d::fromTransformation(m * mp.inverse());
}

/// The angle α in S^R of the parametric direction y, i.e. of M_p y measured from the x
/// axis of S^R (the angle to use in eq. 2.4 for a direction given in (u, v)). Throws
/// MeshingError when M_p is singular / not finite or y is zero / not finite.
inline double angleInRealSpace(const Mat2& mp, const Vec2& y) {
  if (!mp.allFinite() || !(mp.determinant() > 0))
    throw MeshingError("the surface's parametrisation is degenerate or not finite there (its derivatives vanish or overflow)");
  const Vec2 e = mp * y;
  if (!(e.allFinite() && e.squaredNorm() > 0))
    throw MeshingError("the surface has no tangent direction there (a zero or non-finite derivative: degenerate geometry)");
  return std::atan2(e.y(), e.x());
}

/// P^M = M P (eq. 2.10).
inline Vec2 toMetricSpace(const Mat2& m, const Vec2& p) { return m * p; }
/// P^R = M_p P (eq. 2.12).
inline Vec2 toRealSpace(const Mat2& mp, const Vec2& p) { return mp * p; }
/// d_M(P1, P2) = |M (P2 − P1)| (eq. 2.11), M constant along the segment.
inline double metricDistance(const Mat2& m, const Vec2& p1, const Vec2& p2) {
  return (m * (p2 - p1)).norm();
}
/// d_R(P1, P2) = |M_p (P2 − P1)| (eq. 2.13): the distance on the surface, M_p constant.
inline double realDistance(const Mat2& mp, const Vec2& p1, const Vec2& p2) {
  return (mp * (p2 - p1)).norm();
}

}  // namespace aniso
