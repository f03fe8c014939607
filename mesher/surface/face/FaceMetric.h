#pragma once
// Metric helpers of the face mesher (thesis sec. 2.2.1, 4.2, 4.5, 6.5), all in the face's
// transformation M = M_s M_p (eq. 2.9), a plain Mat2 (not symmetric in general):
//
//   metricAt(cs, uv)          M at a parametric point (one control-space call).
//   triangleQuality(M, a,b,c) q(K) = S_oI / S_oK (eq. 4.1): the area of the circumcircle of
//                             the ideal (unit equilateral) triangle over that of K mapped
//                             by M, i.e. q = 1 / (3 R_M²) = 4 (2A_M)² / (3 l_1² l_2² l_3²);
//                             1 for the unit triangle, < 1 when K is too large or badly
//                             shaped, 0 for a degenerate K. Sensitive to size and shape.
//   metricCircumcenter(M, …)  the centre of the circumcircle of K in metric space, mapped
//                             back to (u, v) (the CCS insertion point of sec. 4.5).
//   metricArea(M, a, b, c)    the area of K in metric space (eq. 6.2 summand).
//   kIdealTriangleArea        S_M(K_I) = √3 / 4 (eq. 6.2).
// Header-only and allocation-free except metricAt (a virtual call).
#include <cmath>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/core/Types.h"

namespace aniso::face {

inline constexpr double kIdealTriangleArea = 0.43301270189221932338;  // √3 / 4

inline Mat2 metricAt(const ControlSpace2d& cs, const Vec2& uv) { return cs.getMetric(uv).transformation(); }

/// Twice the signed area of the parallelogram spanned by x and y.
inline double cross2(const Vec2& x, const Vec2& y) { return x.x() * y.y() - x.y() * y.x(); }

inline double triangleQuality(const Mat2& m, const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 e1 = m * (b - a), e2 = m * (c - a), e3 = e2 - e1;
  const double twiceArea = cross2(e1, e2);
  const double den = e1.squaredNorm() * e2.squaredNorm() * e3.squaredNorm();
  if (!(den > 0) || !(twiceArea > 0)) return 0.0;
  const double q = 4.0 * twiceArea * twiceArea / (3.0 * den);
  return std::isfinite(q) ? q : 0.0;
}

inline double metricArea(const Mat2& m, const Vec2& a, const Vec2& b, const Vec2& c) {
  return 0.5 * std::abs(cross2(m * (b - a), m * (c - a)));
}

/// False (c unchanged) when K is degenerate in metric space or M is singular.
inline bool metricCircumcenter(const Mat2& m, const Vec2& a, const Vec2& b, const Vec2& c, Vec2& centre) {
  const Vec2 e1 = m * (b - a), e2 = m * (c - a);
  const double d = 2.0 * cross2(e1, e2);
  const double det = m.determinant();
  if (!(std::abs(d) > 0) || !(std::abs(det) > 0)) return false;
  const double l1 = e1.squaredNorm(), l2 = e2.squaredNorm();
  const Vec2 cm((e2.y() * l1 - e1.y() * l2) / d, (e1.x() * l2 - e2.x() * l1) / d);
  // M⁻¹ cm by the adjugate.
  const Vec2 back((m(1, 1) * cm.x() - m(0, 1) * cm.y()) / det, (m(0, 0) * cm.y() - m(1, 0) * cm.x()) / det);
  const Vec2 r = a + back;
  if (!r.allFinite()) return false;
  centre = r;
  return true;
}

}  // namespace aniso::face
