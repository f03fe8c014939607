#include "mesher/surface/contour/VertexNearEdge.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "mesher/core/Segment.h"
#include "mesher/surface/contour/PeriodicUv.h"

namespace aniso::contour {
namespace {

struct Corner {
  int vertex = -1;
  Vec2 uv;
};

/// The corners of face f's loops: each use's two ends on its pcurve.
std::vector<Corner> corners(const Model& model, int f) {
  std::vector<Corner> out;
  for (const Loop& loop : model.faces[static_cast<std::size_t>(f)].loops)
    for (const EdgeUse& u : loop.uses) {
      const ModelEdge& ed = model.edges[static_cast<std::size_t>(u.edge)];
      if (u.pcurve < 0 || static_cast<std::size_t>(u.pcurve) >= ed.pcurves.size()) continue;
      const PCurve& pc = ed.pcurves[static_cast<std::size_t>(u.pcurve)];
      if (!pc.curve) continue;
      out.push_back({ed.v0, pc.curve->point(ed.t0)});
      out.push_back({ed.v1, pc.curve->point(ed.t1)});
    }
  return out;
}

/// One pass over face f: the parameters to add, by edge.
void passOverFace(const Model& model, int f, const std::vector<std::vector<double>>& t,
                  std::map<int, std::set<double>>& add) {
  const ModelFace& face = model.faces[static_cast<std::size_t>(f)];
  const PeriodicUv periodic(face.surface->domain(), Box2{});
  const std::vector<Corner> cs = corners(model, f);
  for (const Loop& loop : face.loops)
    for (const EdgeUse& u : loop.uses) {
      const ModelEdge& ed = model.edges[static_cast<std::size_t>(u.edge)];
      const std::vector<double>& te = t[static_cast<std::size_t>(u.edge)];
      if (ed.degenerate || te.size() < 2 || u.pcurve < 0 || static_cast<std::size_t>(u.pcurve) >= ed.pcurves.size())
        continue;
      const ParametricCurve2d* c = ed.pcurves[static_cast<std::size_t>(u.pcurve)].curve.get();
      if (!c) continue;
      Vec2 a = c->point(te[0]);
      for (std::size_t i = 0; i + 1 < te.size(); ++i) {
        const double t0 = te[i], t1 = te[i + 1];
        const Vec2 b = c->point(t1);
        double sag = 0;
        Box2 box;
        box.add(a);
        box.add(b);
        for (const double q : {0.25, 0.5, 0.75}) {
          const Vec2 m = c->point(t0 + q * (t1 - t0));
          sag = std::max(sag, distanceToSegment(m, a, b));
          box.add(m);
        }
        const double reach = kNearVertexSagitta * sag;
        if (sag > 0 && std::isfinite(sag)) {
          const Vec2 centre = 0.5 * (box.lo + box.hi);
          for (const Corner& k : cs) {
            if (k.vertex == ed.v0 || k.vertex == ed.v1) continue;
            const Vec2 p = k.uv + periodic.shiftToward(k.uv, centre);
            if ((p.array() < box.lo.array() - reach).any() || (p.array() > box.hi.array() + reach).any()) continue;
            const double ts = c->project(p, 0.5 * (t0 + t1), t0, t1);
            const double margin = kNearVertexMargin * (t1 - t0);
            if (!(ts > t0 + margin && ts < t1 - margin)) continue;
            const double d = (c->point(ts) - p).norm();
            // a corner on the edge itself (d = 0) is a touching loop: no node helps there
            if (d < reach && d > 1e-9 * (b - a).norm()) add[u.edge].insert(ts);
          }
        }
        a = b;
      }
    }
}

}  // namespace

int addNodesNearVertices(const Model& model, const std::vector<const ControlSpace2d*>& spaces,
                         std::vector<std::vector<double>>& t) {
  int added = 0;
  for (int round = 0; round < kNearVertexRounds; ++round) {
    std::map<int, std::set<double>> add;
    for (int f = 0; f < static_cast<int>(model.faces.size()); ++f)
      if (spaces[static_cast<std::size_t>(f)]) passOverFace(model, f, t, add);
    if (add.empty()) break;
    int now = 0;
    for (const auto& [e, ts] : add) {
      std::vector<double>& te = t[static_cast<std::size_t>(e)];
      // several corners (or one seen from two faces) in one segment: nodes kept apart by
      // the margin, in increasing order
      std::vector<double> keep;
      for (const double x : ts) {
        const auto hi = std::upper_bound(te.begin(), te.end(), x);
        if (hi == te.begin() || hi == te.end()) continue;
        const double lo = *(hi - 1), margin = kNearVertexMargin * (*hi - lo);
        if (x - std::max(lo, keep.empty() ? lo : keep.back()) > margin && *hi - x > margin) keep.push_back(x);
      }
      te.insert(te.end(), keep.begin(), keep.end());
      std::sort(te.begin(), te.end());
      now += static_cast<int>(keep.size());
    }
    added += now;
    if (now == 0) break;
  }
  return added;
}

}  // namespace aniso::contour
