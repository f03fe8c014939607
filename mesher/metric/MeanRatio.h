#pragma once
// Mean ratio shape measure η and its metric-space version η_M (sec. 2.5.1, eq. 2.47).
//
//   triangle:     η = 4√3 S / Σ l_ij²          (S signed area)
//   tetrahedron:  η = 12 (9 V²)^{1/3} / Σ l_ij²  times sign(V)  (V signed volume)
//
// η = 1 for an equilateral simplex, 0 < η < 1 otherwise; η = 0 for a degenerate simplex
// (collinear / coplanar points, including coincident points: never NaN). Signed
// convention: η < 0 for an inverted simplex (clockwise triangle, tetrahedron with
// negative volume (p2−p1)·((p3−p1)×(p4−p1)) < 0), with |η| the shape quality; so η > 0
// is the validity test as well.
//
// η_M: the vertices are first mapped to metric space with one transformation tensor for
// the whole simplex (the caller's average / representative-point metric, sec. 2.5.1). A
// transformation with positive determinant (every Metric, and M = M_s M_p) keeps the
// orientation. The mesh value η̄_M (eq. 2.48) is the mean over elements: QualityStats.
// Inline, allocation-free, no checks (non-finite input gives non-finite output).
#include <Eigen/Geometry>
#include <cmath>

#include "mesher/metric/Metric.h"

namespace aniso {

inline double meanRatio(const Vec2& p1, const Vec2& p2, const Vec2& p3) {
  const Vec2 a = p2 - p1, b = p3 - p1, c = p3 - p2;
  const double sum = a.squaredNorm() + b.squaredNorm() + c.squaredNorm();
  const double area = 0.5 * (a.x() * b.y() - a.y() * b.x());
  return sum > 0 ? 4 * std::sqrt(3.0) * area / sum : 0.0;
}

/// A triangle in space: 4√3 area / Σ edge², 1 for the equilateral one, never negative.
inline double meanRatio(const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  const double sum = (p2 - p1).squaredNorm() + (p3 - p2).squaredNorm() + (p1 - p3).squaredNorm();
  return sum > 0 ? 2 * std::sqrt(3.0) * (p2 - p1).cross(p3 - p1).norm() / sum : 0.0;
}

inline double meanRatio(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const Vec3 a = p2 - p1, b = p3 - p1, c = p4 - p1;
  const double sum = a.squaredNorm() + b.squaredNorm() + c.squaredNorm() + (p3 - p2).squaredNorm() +
                     (p4 - p2).squaredNorm() + (p4 - p3).squaredNorm();
  const double volume = a.dot(b.cross(c)) / 6;
  if (!(sum > 0)) return 0.0;
  return std::copysign(12 * std::cbrt(9 * volume * volume) / sum, volume);
}

/// η_M of a triangle with a symmetric metric (planar meshing).
inline double meanRatio(const Metric2d& m, const Vec2& p1, const Vec2& p2, const Vec2& p3) {
  return meanRatio(m.apply(p1), m.apply(p2), m.apply(p3));
}
/// η_M of a triangle in a parametric plane with the surface transformation M = M_s M_p.
inline double meanRatio(const Mat2& m, const Vec2& p1, const Vec2& p2, const Vec2& p3) {
  return meanRatio(Vec2(m * p1), Vec2(m * p2), Vec2(m * p3));
}
/// η_M of a tetrahedron.
inline double meanRatio(const Metric3d& m, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                        const Vec3& p4) {
  return meanRatio(m.apply(p1), m.apply(p2), m.apply(p3), m.apply(p4));
}

}  // namespace aniso
