#include "mesher/quad/TransitionSplit.h"

#include <algorithm>
#include <vector>

#include "mesher/quad/SideEdge.h"

namespace aniso::quad {
namespace {

/// The ring reversed (counter-clockwise ↔ clockwise), triangles and quads.
Corners reversed(const Corners& c) {
  return c[3] == kNone ? Corners{c[0], c[2], c[1], kNone} : Corners{c[0], c[3], c[2], c[1]};
}

void place(QuadMesh2d& mesh, VertexMetrics& metrics, int v, const Vec2& p) {
  mesh.uv[v] = p;
  metrics.invalidate(v);
}

}  // namespace

TransitionResult transitionSplit(QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, bool left,
                                 double seamAngle, const TransitionSplitOptions& o) {
  TransitionResult r;
  const int v = mesh.corners[e][left ? k : (k + 1) % 3];
  if (mesh.boundary[v]) return r;
  const RegionFan fan = regionFan(mesh, metrics, v, e, left);
  if (fan.closed || fan.triangles.size() > 2 || !(fan.angle.back() >= seamAngle)) return r;
  const int u0 = fan.rays.front(), u1 = fan.rays.back();
  const double l0 = metrics.length(v, u0), l1 = metrics.length(v, u1);
  const bool longBase = l0 >= l1;
  if (!(std::max(l0, l1) > o.splitRatio * std::min(l0, l1)) || !(std::max(l0, l1) >= o.minLongLength)) return r;
  const int L = longBase ? u0 : u1, s = longBase ? u1 : u0;
  // From L to s around v: counter-clockwise (dir) or clockwise; the rings below are
  // written for dir and reversed otherwise.
  const bool dir = left == longBase;
  const int n = static_cast<int>(fan.triangles.size());
  const int first = longBase ? fan.triangles.front() : fan.triangles.back();
  const int t = n == 2 ? fan.rays[1] : kNone;
  const int idx = dir ? mesh.edgeIndex(first, v, L) : mesh.edgeIndex(first, L, v);
  if (idx == kNone) return r;
  const int q0 = mesh.adj[first][idx];
  if (q0 == kNone || !mesh.isQuad(q0)) return r;
  const Corners quad = mesh.corners[q0];
  const int j = mesh.cornerIndex(q0, v);
  if (quad[dir ? (j + 3) % 4 : (j + 1) % 4] != L) return r;
  const int q = quad[dir ? (j + 1) % 4 : (j + 3) % 4], p = quad[(j + 2) % 4];
  if (mesh.cornerIndex(q0, s) != kNone || (t != kNone && mesh.cornerIndex(q0, t) != kNone)) return r;
  // The elements around v that stay (v moves under them).
  std::vector<int> around, others;
  bool closed = false;
  mesh.star(v, q0, around, closed);
  if (!closed) return r;
  for (int f : around)
    if (f != q0 && std::find(fan.triangles.begin(), fan.triangles.end(), f) == fan.triangles.end()) others.push_back(f);
  std::vector<double> before;
  for (int f : others) before.push_back(elementQuality(mesh, metrics, mesh.corners[f]));

  const Vec2 old = mesh.uv[v];
  const int m = mesh.addVertex(0.5 * (mesh.uv[v] + mesh.uv[L]));
  const int c = mesh.addVertex(old);
  metrics.invalidate(m);
  std::vector<Corners> added{Corners{v, q, p, c}, Corners{c, p, L, m}, Corners{v, c, m, s}};
  if (n == 2) {
    added.push_back({m, L, t, kNone});
    added.push_back({m, t, s, kNone});
  } else {
    added.push_back({m, L, s, kNone});
  }
  if (!dir)
    for (Corners& x : added) x = reversed(x);
  // Worst of the three quads, or −1 when anything is illegal.
  const auto score = [&]() {
    double worst = 2;
    for (std::size_t i = 0; i < added.size(); ++i) {
      const double x = elementQuality(mesh, metrics, added[i]);
      if (!(x > 0) || (i < 3 && x < o.minQuality)) return -1.0;
      if (i < 3) worst = std::min(worst, x);
    }
    for (std::size_t i = 0; i < others.size(); ++i) {
      const double x = elementQuality(mesh, metrics, mesh.corners[others[i]]);
      if (!(x > 0) || (mesh.isQuad(others[i]) && x < std::min(o.minQuality, before[i]))) return -1.0;
    }
    return worst;
  };
  double best = 0;
  Vec2 bestV = old, bestC = old;
  for (double f : o.moveFractions) {
    const Vec2 pv = old + f * (mesh.uv[q] - old);
    const Vec2 centre[2] = {(pv + mesh.uv[m] + mesh.uv[L] + mesh.uv[p] + mesh.uv[q]) / 5.0,
                            (pv + mesh.uv[m] + mesh.uv[p]) / 3.0};
    for (const Vec2& pc : centre) {
      place(mesh, metrics, v, pv);
      place(mesh, metrics, c, pc);
      const double x = score();
      if (x > best) {
        best = x;
        bestV = pv;
        bestC = pc;
      }
    }
  }
  if (!(best > 0)) {
    place(mesh, metrics, v, old);
    mesh.removeLastVertex();
    mesh.removeLastVertex();
    metrics.invalidate(c);
    metrics.invalidate(m);
    return r;
  }
  place(mesh, metrics, v, bestV);
  place(mesh, metrics, c, bestC);
  std::vector<int> removed{q0};
  for (int f : fan.triangles) removed.push_back(f);
  const std::vector<int> ids = mesh.replacePatch(removed, added);
  r.done = true;
  r.vertex = m;
  r.reshaped = ids[0];
  r.extra = ids[1];
  r.quad = ids[2];
  r.from = q0;
  return r;
}

}  // namespace aniso::quad
