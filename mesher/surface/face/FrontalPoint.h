#pragma once
// Frontal point placement (Rebay 1993, the "frontal Delaunay" method Gmsh's front2d uses),
// in the metric of the face: the new point of a bad triangle K = (a, b, c) that borders the
// front along edge (a, b) — the edge is a contour or is shared with an accepted triangle —
// lies on the perpendicular bisector of (a, b), on c's side, where the triangle it forms
// with (a, b) has the circumradius of the ideal unit triangle (1/√3) in metric space: for a
// unit edge this is the apex of the unit equilateral triangle:
//   ρ = max(1/√3, p),   d = min(ρ + √(ρ² − p²), q + 0.9 R),   P = mid + d n
// with p half the metric edge length, q the signed distance from the edge's midpoint to
// K's metric circumcentre along the unit normal n towards c and R K's metric circumradius.
// ρ ≥ p gives a too long front edge the apex of the equilateral triangle on it; the bound
// on d keeps P inside K's circumcircle (a tenth of R from it), so P's Delaunay cavity
// contains K and K is replaced.
// Returns false (p unchanged) for q ≤ 0 (K's circumcentre behind the front edge: the angle
// at c is obtuse and the bound is undefined), a degenerate K or a singular m.
#include <cmath>

#include "mesher/core/Types.h"

namespace aniso::face {

inline bool frontalPoint(const Mat2& m, const Vec2& a, const Vec2& b, const Vec2& c, Vec2& p) {
  const double det = m.determinant();
  if (!(std::abs(det) > 0)) return false;
  const Vec2 e = m * (b - a), w = m * (c - a);
  const double len = e.norm();
  if (!(len > 0)) return false;
  Vec2 n(-e.y(), e.x());
  n /= len;
  if (n.dot(w) < 0) n = -n;
  const double half = 0.5 * len;
  // Circumcentre of (0, e, w) in metric space: on the bisector x·e = |e|²/2.
  const double d2 = 2.0 * (e.x() * w.y() - e.y() * w.x());
  if (!(std::abs(d2) > 0)) return false;
  const double le = e.squaredNorm(), lw = w.squaredNorm();
  const Vec2 centre((w.y() * le - e.y() * lw) / d2, (e.x() * lw - w.x() * le) / d2);
  const Vec2 mid = 0.5 * e;
  const double q = (centre - mid).dot(n);
  if (!(q > 0)) return false;
  constexpr double kIdealCircumradius = 0.57735026918962576451;  // 1/√3
  const double rho = std::max(kIdealCircumradius, half);
  const double radius = std::sqrt(half * half + q * q);
  const double d = std::min(rho + std::sqrt(std::max(rho * rho - half * half, 0.0)), q + 0.9 * radius);
  const Vec2 target = mid + d * n;
  // Back to (u, v): a + M⁻¹ target, by the adjugate.
  const Vec2 back((m(1, 1) * target.x() - m(0, 1) * target.y()) / det,
                  (m(0, 0) * target.y() - m(1, 0) * target.x()) / det);
  const Vec2 r = a + back;
  if (!r.allFinite()) return false;
  p = r;
  return true;
}

}  // namespace aniso::face
