#include "mesher/surface/contour/CornerParity.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

#include "mesher/core/Log.h"

namespace aniso::contour {
namespace {

/// Fraction of a use's parameter range spanned by the chord that stands for its tangent:
/// short enough to be local, long enough to see the side a tangential cusp opens to.
constexpr double kChordFraction = 1e-3;

/// Chord from the vertex along use u (leaving the vertex when `leaving`, else arriving).
Vec3 chord(const ModelEdge& e, const EdgeUse& u, bool leaving) {
  const double dt = kChordFraction * (e.t1 - e.t0);
  // Walking forward: leaves from t0 and arrives at t1; reversed: leaves t1, arrives t0.
  const bool atStart = leaving != u.reversed;
  const double tv = atStart ? e.t0 : e.t1, tn = atStart ? e.t0 + dt : e.t1 - dt;
  const Vec3 away = e.curve->point(tn) - e.curve->point(tv);
  return leaving ? away : Vec3(-away);
}

}  // namespace

std::vector<LoopCorner> sharpCornerList(const Model& model, int f) {
  const ModelFace& face = model.faces[f];
  std::vector<LoopCorner> out;
  for (std::size_t l = 0; l < face.loops.size(); ++l) {
    const Loop& loop = face.loops[l];
    const std::size_t m = loop.uses.size();
    for (std::size_t j = 0; j < m; ++j) {
      // The corner before use j: from the last use before it that is not degenerate (a
      // pole between two edges makes one corner of them, often a tangential cusp).
      std::size_t i = (j + m - 1) % m;
      while (i != j && model.edges[loop.uses[i].edge].degenerate) i = (i + m - 1) % m;
      const EdgeUse& a = loop.uses[i];
      const EdgeUse& b = loop.uses[j];
      const ModelEdge& ea = model.edges[a.edge];
      const ModelEdge& eb = model.edges[b.edge];
      if (i == j || ea.degenerate || eb.degenerate || !ea.curve || !eb.curve || b.pcurve < 0) continue;
      // A seam edge back to itself around a pole (a full sphere's loop) turns all the way
      // round the pole: no corner.
      if (a.edge == b.edge && i != (j + m - 1) % m) continue;
      // The normal a chord's length into b: at a pole the surface has none.
      const PCurve& pc = eb.pcurves[b.pcurve];
      const double dt = kChordFraction * (pc.t1 - pc.t0);
      const Vec2 uv = pc.curve->point(b.reversed ? pc.t1 - dt : pc.t0 + dt);
      Vec3 nrm = face.surface->normal(uv);
      if (face.reversed) nrm = -nrm;
      Vec3 tin = chord(ea, a, false), tout = chord(eb, b, true);
      tin -= tin.dot(nrm) * nrm;
      tout -= tout.dot(nrm) * nrm;
      if (!(tin.norm() > 0) || !(tout.norm() > 0) || !tin.allFinite() || !tout.allFinite()) continue;
      // Left turn from the arriving to the leaving direction; interior = π − turn.
      const double turn = std::atan2(nrm.dot(tin.cross(tout)), tin.dot(tout));
      if (std::numbers::pi - turn < kQuadCornerAngle)
        out.push_back({static_cast<int>(l), static_cast<int>(i), static_cast<int>(j)});
    }
  }
  return out;
}

int makeCornerParity(const Model& model, const std::vector<const ControlSpace2d*>& spaces,
                     const std::vector<char>& used, std::vector<int>& n) {
  const int nf = static_cast<int>(model.faces.size());
  const int freeNode = nf;
  std::vector<int> demand(nf + 1, 0);
  bool any = false;
  int oddFaces = 0;
  for (int f = 0; f < nf; ++f)
    if (spaces[f] && sharpCorners(model, f) % 2) demand[f] = 1, any = true, ++oddFaces;
  if (!any) return 0;

  // Links: per edge, the meshed faces using it an odd number of times.
  struct Link {
    int edge, to;
  };
  // One pass over the loops: per edge, its uses by meshed faces (in face order).
  std::vector<std::map<int, int>> usesOf(model.edges.size());
  for (int f = 0; f < nf; ++f) {
    if (!spaces[f]) continue;
    for (const Loop& loop : model.faces[f].loops)
      for (const EdgeUse& u : loop.uses) ++usesOf[u.edge][f];
  }
  std::vector<std::vector<Link>> adj(nf + 1);
  for (int e = 0; e < static_cast<int>(model.edges.size()); ++e) {
    if (!used[e] || model.edges[e].degenerate) continue;
    std::vector<int> odd;
    for (const auto& [f, k] : usesOf[e])
      if (k % 2) odd.push_back(f);
    if (odd.size() == 1) odd.push_back(freeNode);
    if (odd.size() != 2) continue;
    adj[odd[0]].push_back({e, odd[1]});
    adj[odd[1]].push_back({e, odd[0]});
  }
  for (auto& links : adj)
    std::sort(links.begin(), links.end(), [&](const Link& a, const Link& b) {
      return n[a.edge] != n[b.edge] ? n[a.edge] > n[b.edge] : a.edge < b.edge;
    });

  // Spanning forest by breadth-first search, then leaves to root: an odd node flips the
  // link to its parent.
  std::vector<int> parentEdge(nf + 1, -1), parent(nf + 1, -1);
  std::vector<char> seen(nf + 1, 0);
  int raised = 0;
  auto grow = [&](int root) {
    std::vector<int> order{root};
    seen[root] = 1;
    for (std::size_t i = 0; i < order.size(); ++i)
      for (const Link& l : adj[order[i]])
        if (!seen[l.to]) {
          seen[l.to] = 1;
          parent[l.to] = order[i];
          parentEdge[l.to] = l.edge;
          order.push_back(l.to);
        }
    for (std::size_t i = order.size(); i-- > 1;) {
      const int v = order[i];
      if (!demand[v]) continue;
      ++n[parentEdge[v]];
      ++raised;
      demand[v] = 0;
      demand[parent[v]] ^= 1;
    }
  };
  grow(freeNode);
  int unmatched = 0;
  for (int f = 0; f < nf; ++f)
    if (!seen[f] && spaces[f]) {
      grow(f);
      unmatched += demand[f];
    }
  logDebug("quad parity: " + std::to_string(oddFaces) + " faces with an odd number of sharp corners, " +
           std::to_string(raised) + " edge counts made odd, " + std::to_string(unmatched) + " faces left unmatched");
  return raised;
}

}  // namespace aniso::contour
