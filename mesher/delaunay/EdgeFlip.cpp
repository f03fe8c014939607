#include "mesher/delaunay/EdgeFlip.h"

#include <vector>

#include "mesher/core/Error.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::del2d {
namespace {

/// Re-points the neighbour n (if any) from `oldT` to `newT`.
void repoint(Triangulation2d& tri, TriId n, TriId oldT, TriId newT) {
  if (!n.valid()) return;
  const int k = tri.neighbourIndex(n, oldT);
  if (k >= 0) tri.setNeighbour(n, k, newT);
}

/// Fills the quadrilateral of edge i of t: returns false without a neighbour.
bool quad(const Triangulation2d& tri, TriId t, int i, FlipPlan& p) {
  p.t = t;
  p.i = i;
  p.a = tri.vertex(t, i);
  p.b = tri.vertex(t, kNext[i]);
  p.c = tri.vertex(t, kPrev[i]);
  p.u = tri.neighbour(t, i);
  if (!p.u.valid()) return false;
  p.j = tri.neighbourIndex(p.u, t);
  if (p.j < 0) return false;
  p.d = tri.vertex(p.u, p.j);
  return true;
}

}  // namespace

FlipPlan canFlip(const Triangulation2d& tri, TriId t, int i) {
  FlipPlan p;
  if (!tri.isAlive(t) || i < 0 || i > 2 || tri.isConstrained(t, i) || !quad(tri, t, i, p)) return p;
  const double* a = tri.coords(p.a);
  const double* b = tri.coords(p.b);
  const double* c = tri.coords(p.c);
  const double* d = tri.coords(p.d);
  p.legal = predicates::orient2d(a, b, d) > 0 && predicates::orient2d(a, d, c) > 0;
  return p;
}

void flip(Triangulation2d& tri, const FlipPlan& p) {
  if (!p.legal) throw MeshingError("flip: the plan is not legal");
  const TriId t = p.t, u = p.u;
  const int i = p.i, j = p.j;
  // Outer neighbours and constrained bits, by edge.
  const TriId nCA = tri.neighbour(t, kNext[i]), nAB = tri.neighbour(t, kPrev[i]);
  const TriId nBD = tri.neighbour(u, kNext[j]), nDC = tri.neighbour(u, kPrev[j]);
  const bool cCA = tri.isConstrained(t, kNext[i]), cAB = tri.isConstrained(t, kPrev[i]);
  const bool cBD = tri.isConstrained(u, kNext[j]), cDC = tri.isConstrained(u, kPrev[j]);
  // t' = (a, b, d): edges (b,d) | (d,a) | (a,b);  u' = (a, d, c): edges (d,c) | (c,a) | (a,d).
  tri.setTriangle(t, p.a, p.b, p.d);
  tri.setTriangle(u, p.a, p.d, p.c);
  tri.setNeighbour(t, 0, nBD), tri.setNeighbour(t, 1, u), tri.setNeighbour(t, 2, nAB);
  tri.setNeighbour(u, 0, nDC), tri.setNeighbour(u, 1, nCA), tri.setNeighbour(u, 2, t);
  repoint(tri, nBD, u, t);
  repoint(tri, nCA, t, u);
  for (int k = 0; k < 3; ++k) {
    tri.setConstrainedBit(t, k, false);
    tri.setConstrainedBit(u, k, false);
  }
  tri.setConstrainedBit(t, 0, cBD), tri.setConstrainedBit(t, 2, cAB);
  tri.setConstrainedBit(u, 0, cDC), tri.setConstrainedBit(u, 1, cCA);
  tri.setVertexTriangle(p.a, t), tri.setVertexTriangle(p.b, t);
  tri.setVertexTriangle(p.d, t), tri.setVertexTriangle(p.c, u);
}

bool violatesEmptyCircle(const Triangulation2d& tri, TriId t, int i, const PlaneTransform& m) {
  FlipPlan p;
  if (!quad(tri, t, i, p)) return false;
  return m.inCircle(tri.point(p.a), tri.point(p.b), tri.point(p.c), m.apply(tri.point(p.d))) > 0;
}

bool violatesInnerAngles(const Triangulation2d& tri, TriId t, int i, const PlaneTransform& m) {
  FlipPlan p;
  if (!quad(tri, t, i, p)) return false;
  const Vec2 a = m.apply(tri.point(p.a)), b = m.apply(tri.point(p.b));
  const Vec2 c = m.apply(tri.point(p.c)), d = m.apply(tri.point(p.d));
  const Vec2 ab = b - a, ac = c - a, db = b - d, dc = c - d;
  const double cosA = ab.dot(ac), cosD = db.dot(dc);
  if (cosA >= 0 && cosD >= 0) return false;  // both angles ≤ π/2
  if (cosA < 0 && cosD < 0) return true;     // both obtuse
  // Unnormalised sines, positive for the counter-clockwise (a,b,c), (d,c,b) in M-space.
  const double sinA = m.orientation() * (ab.x() * ac.y() - ab.y() * ac.x());
  const double sinD = m.orientation() * (dc.x() * db.y() - dc.y() * db.x());
  return sinA * cosD + cosA * sinD < 0;  // sin(α + δ) < 0  ⇔  α + δ > π
}

FlipStats restoreDelaunay(Triangulation2d& tri, std::span<const TriId> start, const PlaneTransform& m,
                          FlipCriterion criterion, std::size_t maxFlips) {
  FlipStats st;
  // Edges are queued as (triangle, local index) codes 3t + i; stale entries are re-read.
  std::vector<std::uint32_t> edges;
  for (TriId t : start)
    if (tri.isAlive(t))
      for (int i = 0; i < 3; ++i) edges.push_back(3 * t.index + static_cast<std::uint32_t>(i));
  while (!edges.empty()) {
    const std::uint32_t code = edges.back();
    edges.pop_back();
    const TriId t(code / 3);
    const int i = static_cast<int>(code % 3);
    if (!tri.isAlive(t) || tri.isConstrained(t, i) || !tri.neighbour(t, i).valid()) continue;
    ++st.checked;
    const bool bad = criterion == FlipCriterion::EmptyCircle ? violatesEmptyCircle(tri, t, i, m)
                                                             : violatesInnerAngles(tri, t, i, m);
    if (!bad) continue;
    const FlipPlan plan = canFlip(tri, t, i);
    if (!plan.legal) continue;
    if (st.flipped == maxFlips) {
      st.limitReached = true;
      break;
    }
    flip(tri, plan);
    ++st.flipped;
    // Outer edges of the new pair: t' = (a,b,d) edges 0 and 2, u' = (a,d,c) edges 0 and 1.
    edges.push_back(3 * plan.t.index + 0), edges.push_back(3 * plan.t.index + 2);
    edges.push_back(3 * plan.u.index + 0), edges.push_back(3 * plan.u.index + 1);
  }
  return st;
}

}  // namespace aniso::del2d
