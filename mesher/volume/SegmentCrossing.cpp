#include "mesher/volume/SegmentCrossing.h"

#include <cmath>

#include "mesher/predicates/Predicates.h"

namespace aniso::volume {
namespace {

using predicates::orient2d;
using predicates::orient3d;

bool same(const double* a, const double* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; }
int sgn(double x) { return (x > 0) - (x < 0); }

/// The two coordinates kept for coplanar tests: drop the axis of the largest component of
/// the (floating-point) normal of the plane through the given points.
struct Plane2d {
  int i = 0, j = 1;
  explicit Plane2d(const double* a, const double* b, const double* c) {
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {std::fabs(u[1] * v[2] - u[2] * v[1]), std::fabs(u[2] * v[0] - u[0] * v[2]),
                         std::fabs(u[0] * v[1] - u[1] * v[0])};
    const int drop = n[0] >= n[1] && n[0] >= n[2] ? 0 : (n[1] >= n[2] ? 1 : 2);
    i = drop == 0 ? 1 : 0;
    j = drop == 2 ? 1 : 2;
  }
  int orient(const double* a, const double* b, const double* c) const {
    const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
    return sgn(orient2d(pa, pb, pc));
  }
};

/// Strictly inside the triangle abc (any orientation) in the plane.
bool strictlyInside(const Plane2d& pl, const double* x, const double* a, const double* b, const double* c) {
  const int s = pl.orient(a, b, c);
  if (s == 0) return false;
  return pl.orient(a, b, x) == s && pl.orient(b, c, x) == s && pl.orient(c, a, x) == s;
}

/// Proper crossing of segments pq and xy in the plane (interiors meet at one point).
bool properCross(const Plane2d& pl, const double* p, const double* q, const double* x, const double* y) {
  const int s1 = pl.orient(p, q, x), s2 = pl.orient(p, q, y);
  const int s3 = pl.orient(x, y, p), s4 = pl.orient(x, y, q);
  return s1 * s2 < 0 && s3 * s4 < 0;
}

}  // namespace

Cross segmentPiercesTriangle(const double* p, const double* q, const double* a, const double* b, const double* c) {
  const int op = sgn(orient3d(a, b, c, p)), oq = sgn(orient3d(a, b, c, q));
  if (op * oq > 0 || (op == 0 && oq == 0)) return Cross::None;
  if (op == 0 || oq == 0) {
    const double* on = op == 0 ? p : q;
    if (same(on, a) || same(on, b) || same(on, c)) return Cross::None;
    return strictlyInside(Plane2d(a, b, c), on, a, b, c) ? Cross::Degenerate : Cross::None;
  }
  const int s1 = sgn(orient3d(p, q, a, b)), s2 = sgn(orient3d(p, q, b, c)), s3 = sgn(orient3d(p, q, c, a));
  if (s1 != 0 && s1 == s2 && s2 == s3) return Cross::Interior;
  return Cross::None;
}

Cross segmentCrossesTriangleInPlane(const double* p, const double* q, const double* a, const double* b,
                                    const double* c) {
  const Plane2d pl(a, b, c);
  const double* tri[3] = {a, b, c};
  int sharedP = -1, sharedQ = -1;
  for (int k = 0; k < 3; ++k) {
    if (same(p, tri[k])) sharedP = k;
    if (same(q, tri[k])) sharedQ = k;
  }
  if (sharedP >= 0 && sharedQ >= 0) return Cross::None;  // an edge of the triangle
  if ((sharedP < 0 && strictlyInside(pl, p, a, b, c)) || (sharedQ < 0 && strictlyInside(pl, q, a, b, c)))
    return Cross::Degenerate;
  if (sharedP >= 0 || sharedQ >= 0) {
    // Leaves vertex v: enters the triangle iff the other end is strictly inside the angle at v.
    const int k = sharedP >= 0 ? sharedP : sharedQ;
    const double* other = sharedP >= 0 ? q : p;
    const double* v = tri[k];
    const double* n1 = tri[(k + 1) % 3];
    const double* n2 = tri[(k + 2) % 3];
    const int s = pl.orient(v, n1, n2);
    if (s == 0) return Cross::None;
    return pl.orient(v, n1, other) == s && pl.orient(v, other, n2) == s ? Cross::Interior : Cross::None;
  }
  for (int k = 0; k < 3; ++k)
    if (properCross(pl, p, q, tri[k], tri[(k + 1) % 3])) return Cross::Interior;
  return Cross::None;
}

Cross segmentCrossesTriangle(const double* p, const double* q, const double* a, const double* b, const double* c) {
  const int op = sgn(orient3d(a, b, c, p)), oq = sgn(orient3d(a, b, c, q));
  if (op == 0 && oq == 0) return segmentCrossesTriangleInPlane(p, q, a, b, c);
  return segmentPiercesTriangle(p, q, a, b, c);
}

Cross segmentsCross(const double* a, const double* b, const double* x, const double* y) {
  if (same(a, x) || same(a, y) || same(b, x) || same(b, y)) return Cross::None;
  if (orient3d(a, b, x, y) != 0) return Cross::None;
  // Coplanar: pick the plane through a, b and whichever of x, y is off the line ab.
  Plane2d pl(a, b, x);
  int sx = pl.orient(a, b, x), sy = pl.orient(a, b, y);
  if (sx == 0 && sy == 0) {
    pl = Plane2d(a, b, y);
    sx = pl.orient(a, b, x);
    sy = pl.orient(a, b, y);
  }
  if (sx == 0 && sy == 0) {
    // Collinear (or the plane choice is degenerate): overlapping interiors are degenerate.
    const double d[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    auto t = [&](const double* p) { return (p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]; };
    const double len = t(b), tx = t(x), ty = t(y);
    const double lo = std::fmin(tx, ty), hi = std::fmax(tx, ty);
    return hi > 0 && lo < len ? Cross::Degenerate : Cross::None;
  }
  const int sa = pl.orient(x, y, a), sb = pl.orient(x, y, b);
  if (sx * sy < 0 && sa * sb < 0) return Cross::Interior;
  if ((sx == 0 && sa * sb < 0) || (sy == 0 && sa * sb < 0)) return Cross::Degenerate;  // x or y inside ab
  if ((sa == 0 && sx * sy < 0) || (sb == 0 && sx * sy < 0)) return Cross::Degenerate;  // a or b inside xy
  return Cross::None;
}

}  // namespace aniso::volume
