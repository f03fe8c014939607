#include "mesher/surface/contour/CuspNodes.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesher/core/Log.h"
#include "mesher/surface/contour/CornerParity.h"

namespace aniso::contour {
namespace {

/// Bisection steps on the distance (each halves the parameter interval).
constexpr int kBisections = 60;

/// The inner nodes of one edge use seen from a corner vertex: the k-th (k = 1, 2, …) is
/// t[index(k)].
struct Side {
  const ModelEdge* edge;
  std::vector<double>* t;
  bool fromEnd;  ///< the corner is at t.back()
  int inner() const { return static_cast<int>(t->size()) - 2; }
  int index(int k) const { return fromEnd ? static_cast<int>(t->size()) - 1 - k : k; }
  double param(int k) const { return (*t)[index(k)]; }
  double distance(int k, const Vec3& v) const { return (edge->curve->point(param(k)) - v).norm(); }
};

/// The parameter of side s at distance r from v, past node k − 1 (already placed): by
/// bisection between it and the first original node j ≥ k farther than r (j within the
/// half of the edge nearer v); NaN when there is none.
double paramAt(const Side& s, int k, const Vec3& v, double r) {
  const auto f = [&](double t) { return (s.edge->curve->point(t) - v).norm() - r; };
  double lo = s.param(k - 1), hi = lo;
  bool found = false;
  for (int j = k; 2 * j <= s.inner() + 1 && !found; ++j) {
    hi = s.param(j);
    found = f(hi) > 0;
  }
  if (!found || !(f(lo) < 0)) return std::nan("");
  const double from = lo, to = hi;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0 ? lo : hi) = mid;
  }
  const double t = 0.5 * (lo + hi);
  // Strictly inside the bracket, so the parameters stay strictly increasing.
  return t > std::min(from, to) && t < std::max(from, to) ? t : std::nan("");
}

/// After nodes 1..k of s were moved (node k from parameter oldK), maps nodes k+1 .. mid − 1
/// (mid = the middle node, which stays) affinely from (oldK, t_mid) onto (t_k, t_mid): the
/// gradation beyond the sliver keeps its shape and the parameters stay increasing.
void remapRest(Side& s, int k, double oldK) {
  const int mid = (s.inner() + 1) / 2;
  const double newK = s.param(k), tm = s.param(mid);
  if (oldK == tm) return;
  for (int j = k + 1; j < mid; ++j) (*s.t)[s.index(j)] = tm + (s.param(j) - tm) * (newK - tm) / (oldK - tm);
}

/// Matches the nodes of sides a and b at corner vertex v; returns the nodes moved.
int matchCorner(Side a, Side b, const Vec3& v) {
  // The sliver: pairs k = 1.. whose separation across (the distance between the two nodes
  // less their difference in distance from v) is below the local segment length.
  std::vector<double> r;
  double ra0 = 0, rb0 = 0;
  for (int k = 1; 2 * k < a.inner() && 2 * k < b.inner(); ++k) {
    const Vec3 pa = a.edge->curve->point(a.param(k)), pb = b.edge->curve->point(b.param(k));
    const double ra = (pa - v).norm(), rb = (pb - v).norm();
    const double h = 0.5 * ((ra - ra0) + (rb - rb0));
    const double across = std::sqrt(std::max(0.0, (pa - pb).squaredNorm() - (ra - rb) * (ra - rb)));
    if (!(h > 0) || !(across < h)) break;
    r.push_back(0.5 * (ra + rb));
    ra0 = ra;
    rb0 = rb;
  }
  // Placed outward, so node k − 1 of each side is already at its new parameter and nodes
  // k.. are still at their old ones.
  int k = 0;
  double oldA = a.param(0), oldB = b.param(0);
  for (; k < static_cast<int>(r.size()); ++k) {
    const double ta = paramAt(a, k + 1, v, r[k]), tb = paramAt(b, k + 1, v, r[k]);
    if (std::isnan(ta) || std::isnan(tb)) break;
    oldA = a.param(k + 1);
    oldB = b.param(k + 1);
    (*a.t)[a.index(k + 1)] = ta;
    (*b.t)[b.index(k + 1)] = tb;
  }
  if (k == 0) return 0;
  remapRest(a, k, oldA);
  remapRest(b, k, oldB);
  return 2 * k;
}
}  // namespace

int matchCuspNodes(const Model& model, const std::vector<const ControlSpace2d*>& spaces,
                   std::vector<std::vector<double>>& t) {
  int moved = 0, corners = 0;
  for (int f = 0; f < static_cast<int>(model.faces.size()); ++f) {
    if (!spaces[f]) continue;
    for (const LoopCorner& c : sharpCornerList(model, f)) {
      const Loop& loop = model.faces[f].loops[c.loop];
      const EdgeUse& in = loop.uses[c.in];
      const EdgeUse& out = loop.uses[c.out];
      if (in.edge == out.edge) continue;
      const ModelEdge& ea = model.edges[in.edge];
      const ModelEdge& eb = model.edges[out.edge];
      if (t[in.edge].size() < 3 || t[out.edge].size() < 3) continue;
      // The arriving use ends at t1 unless reversed; the leaving use starts at t0 unless reversed.
      const int vertex = in.reversed ? ea.v0 : ea.v1;
      if (vertex < 0 || vertex != (out.reversed ? eb.v1 : eb.v0)) continue;
      const Side a{&ea, &t[in.edge], !in.reversed};
      const Side b{&eb, &t[out.edge], out.reversed};
      moved += matchCorner(a, b, model.vertices[vertex].p);
      ++corners;
    }
  }
  if (corners > 0)
    logDebug("cusp nodes: " + std::to_string(corners) + " sharp corners, " + std::to_string(moved) + " edge nodes matched");
  return moved;
}

}  // namespace aniso::contour
