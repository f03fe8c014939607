#include "mesher/surface/contour/CoincidentEdges.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <utility>

namespace aniso::contour {
namespace {

/// Twin test slack relative to the chord, for curves whose CAD tolerance is below the
/// round-off of two parameterizations of one curve.
constexpr double kTwinFloor = 1e-9;

int findRoot(std::vector<int>& parent, int v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

/// Largest distance from the points of `e` at the given fractions of its range to the curve
/// of `a`.
double distanceToCurve(const ModelEdge& e, const ModelEdge& a, const std::vector<double>& fractions) {
  double worst = 0;
  for (const double f : fractions) {
    const Vec3 p = e.curve->point(e.t0 + f * (e.t1 - e.t0));
    const double ta = a.curve->project(p, a.t0 + f * (a.t1 - a.t0), a.t0, a.t1);
    const double d = (a.curve->point(ta) - p).norm();
    if (!(d == d)) return d;  // NaN: not comparable
    worst = std::max(worst, d);
  }
  return worst;
}

/// Samples along an edge's curve for its length against the floor.
constexpr int kShortEdgeSamples = 8;

/// The edge's curve length (a polyline of kShortEdgeSamples pieces) is at most `floor`.
bool shorterThan(const ModelEdge& ed, double floor) {
  if (!(floor > 0) || !ed.curve) return false;
  double length = 0;
  Vec3 prev = ed.curve->point(ed.t0);
  for (int i = 1; i <= kShortEdgeSamples; ++i) {
    const Vec3 p = ed.curve->point(ed.t0 + (ed.t1 - ed.t0) * i / kShortEdgeSamples);
    length += (p - prev).norm();
    prev = p;
  }
  return length <= floor;
}

}  // namespace

bool collapsedEdge(const Model& model, int e, const std::vector<int>& rep) {
  const ModelEdge& ed = model.edges[static_cast<std::size_t>(e)];
  return !ed.degenerate && ed.v0 != ed.v1 && ed.v0 >= 0 && ed.v1 >= 0 && rep[ed.v0] == rep[ed.v1];
}

std::vector<int> coincidentVertices(const Model& model, const std::vector<char>& usedEdges, double floor) {
  const int nv = static_cast<int>(model.vertices.size());
  std::vector<int> rep(nv);
  std::iota(rep.begin(), rep.end(), 0);
  std::vector<char> used(nv, 0);
  std::set<std::pair<int, int>> edgeEnds;  // open edges' end pairs, never merged
  double maxTol = 0;
  for (std::size_t e = 0; e < model.edges.size(); ++e) {
    const ModelEdge& ed = model.edges[e];
    if (!usedEdges[e] || ed.v0 < 0 || ed.v1 < 0 || ed.v0 >= nv || ed.v1 >= nv) continue;
    used[ed.v0] = used[ed.v1] = 1;
    if (ed.v0 != ed.v1 && !shorterThan(ed, floor)) edgeEnds.insert(std::minmax(ed.v0, ed.v1));
  }
  if (!(floor > 0)) floor = 0;
  std::vector<int> order;
  for (int v = 0; v < nv; ++v)
    if (used[v]) {
      order.push_back(v);
      maxTol = std::max(maxTol, model.vertices[v].tolerance);
    }
  std::sort(order.begin(), order.end(), [&model](int a, int b) {
    const double xa = model.vertices[a].p.x(), xb = model.vertices[b].p.x();
    return xa != xb ? xa < xb : a < b;
  });
  std::vector<int> parent(rep);
  for (std::size_t i = 0; i < order.size(); ++i) {
    const ModelVertex& a = model.vertices[order[i]];
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const ModelVertex& b = model.vertices[order[j]];
      if (b.p.x() - a.p.x() > std::max(maxTol, floor)) break;  // sweep along x: no later vertex is closer
      const double tol = std::max(std::min(a.tolerance, b.tolerance), floor);
      if ((a.p - b.p).norm() > tol || edgeEnds.count(std::minmax(order[i], order[j]))) continue;
      const int ra = findRoot(parent, order[i]), rb = findRoot(parent, order[j]);
      if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
    }
  }
  for (int v = 0; v < nv; ++v) rep[v] = findRoot(parent, v);
  // a group must not join the two ends of a longer open edge through a third vertex
  for (std::size_t e = 0; e < model.edges.size(); ++e) {
    const ModelEdge& ed = model.edges[e];
    if (!usedEdges[e] || ed.v0 == ed.v1 || ed.v0 < 0 || ed.v1 < 0 || ed.v0 >= nv || ed.v1 >= nv) continue;
    if (!edgeEnds.count(std::minmax(ed.v0, ed.v1))) continue;  // shorter than the floor
    if (rep[ed.v0] == rep[ed.v1]) {
      std::iota(rep.begin(), rep.end(), 0);  // ambiguous: keep the CAD's vertices as they are
      return rep;
    }
  }
  return rep;
}

EdgeTwins coincidentEdges(const Model& model, const std::vector<char>& usedEdges, const std::vector<int>& rep,
                          double floor) {
  const int ne = static_cast<int>(model.edges.size());
  EdgeTwins twins;
  twins.of.assign(ne, -1);
  twins.reversed.assign(ne, 0);
  std::map<std::pair<int, int>, std::vector<int>> byEnds;
  for (int e = 0; e < ne; ++e) {
    const ModelEdge& ed = model.edges[e];
    if (!usedEdges[e] || ed.degenerate || !ed.curve || ed.v0 < 0 || ed.v1 < 0) continue;
    const int p = rep[ed.v0], q = rep[ed.v1];
    if (p == q) continue;
    std::vector<int>& earlier = byEnds[std::minmax(p, q)];
    for (const int a : earlier) {
      if (twins.of[a] >= 0) continue;
      const ModelEdge& ea = model.edges[a];
      const double chord = (model.vertices[p].p - model.vertices[q].p).norm();
      const double tol = std::max({ea.tolerance, ed.tolerance, kTwinFloor * chord, floor});
      if (!(distanceToCurve(ed, ea, {0.25, 0.5, 0.75}) <= tol) || !(distanceToCurve(ea, ed, {0.5}) <= tol)) continue;
      twins.of[e] = a;
      twins.reversed[e] = rep[ed.v0] != rep[ea.v0];
      ++twins.count;
      break;
    }
    if (twins.of[e] < 0) earlier.push_back(e);
  }
  return twins;
}

}  // namespace aniso::contour
