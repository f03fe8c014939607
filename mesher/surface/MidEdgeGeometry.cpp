// MidEdgeGeometry — placement of mid-edge nodes on model curves and surfaces (Order2.h).
#include "mesher/surface/MidEdgeGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "mesher/core/Error.h"
#include "mesher/model/EdgePoint.h"
#include "mesher/surface/contour/PeriodicUv.h"

namespace aniso {
namespace {

/// A mid node candidate farther than this (times the edge length) from the chord midpoint
/// is distrusted: the (u, v) midpoint went the wrong way round a closed surface, or the
/// projection converged elsewhere; other starting points are then tried.
constexpr double kMaxProjectionShift = 0.5;

std::uint64_t edgeKey(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

/// Faces that have at least one element in the mesh.
std::vector<char> meshedFaces(const Model& model, const SurfaceMesh& mesh) {
  std::vector<char> used(model.faces.size(), 0);
  auto mark = [&](int f) {
    if (f >= 0 && static_cast<std::size_t>(f) < used.size()) used[f] = 1;
  };
  for (int f : mesh.triangleFace) mark(f);
  for (int f : mesh.quadFace) mark(f);
  return used;
}

}  // namespace

MidEdgeGeometry::MidEdgeGeometry(const Model& model, const SurfaceMesh& mesh)
    : model_(model), mesh_(mesh), vertexEdges_(model.vertices.size()) {
  const int ne = static_cast<int>(model.edges.size());
  for (int e = 0; e < ne; ++e) {
    const ModelEdge& ed = model.edges[e];
    for (int v : {ed.v0, ed.v1})
      if (v >= 0 && static_cast<std::size_t>(v) < vertexEdges_.size() &&
          (vertexEdges_[v].empty() || vertexEdges_[v].back() != e))
        vertexEdges_[v].push_back(e);
  }

  std::vector<int> vertexNode(model.vertices.size(), -1);
  std::vector<std::vector<std::pair<double, int>>> edgeNodes(model.edges.size());
  for (std::size_t i = 0; i < mesh.nodeOn.size(); ++i) {
    const NodeOn& on = mesh.nodeOn[i];
    const std::string where = "order 2: node " + std::to_string(i) + " lies on ";
    if (on.kind == NodeOn::Kind::Vertex) {
      if (on.entity < 0 || static_cast<std::size_t>(on.entity) >= model.vertices.size())
        throw MeshingError(where + "vertex " + std::to_string(on.entity + 1) + ", not in the model");
      if (vertexNode[on.entity] < 0) vertexNode[on.entity] = static_cast<int>(i);
    } else if (on.kind == NodeOn::Kind::Edge) {
      if (on.entity < 0 || on.entity >= ne)
        throw MeshingError(where + "edge " + std::to_string(on.entity + 1) + ", not in the model");
      edgeNodes[on.entity].emplace_back(on.t, static_cast<int>(i));
    } else if (on.kind == NodeOn::Kind::Face) {
      if (on.entity < 0 || static_cast<std::size_t>(on.entity) >= model.faces.size())
        throw MeshingError(where + "face " + std::to_string(on.entity + 1) + ", not in the model");
    }
  }

  // Each used model edge's chain v0, nodes by t, v1: consecutive nodes make a mesh edge on it.
  const std::vector<char> faceUsed = meshedFaces(model, mesh);
  for (int e = 0; e < ne; ++e) {
    const ModelEdge& ed = model.edges[e];
    if (ed.degenerate || !ed.curve) continue;
    if (std::none_of(ed.faces.begin(), ed.faces.end(), [&](int f) {
          return f >= 0 && static_cast<std::size_t>(f) < faceUsed.size() && faceUsed[f];
        }))
      continue;
    if (ed.v0 < 0 || ed.v1 < 0 || static_cast<std::size_t>(std::max(ed.v0, ed.v1)) >= vertexNode.size()) continue;
    if (vertexNode[ed.v0] < 0 || vertexNode[ed.v1] < 0) continue;
    std::vector<std::pair<double, int>>& chain = edgeNodes[e];
    std::sort(chain.begin(), chain.end());
    chain.insert(chain.begin(), {ed.t0, vertexNode[ed.v0]});
    chain.emplace_back(ed.t1, vertexNode[ed.v1]);
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      const auto [t0, n0] = chain[i];
      const auto [t1, n1] = chain[i + 1];
      if (n0 == n1) continue;
      links_.emplace(edgeKey(n0, n1), n0 < n1 ? Link{e, t0, t1} : Link{e, t1, t0});
    }
  }
}

MidNode MidEdgeGeometry::place(int a, int b, int face) const {
  const auto it = links_.find(edgeKey(a, b));
  if (it != links_.end()) return onCurve(a, b, it->second);
  return onSurface(a, b, face);
}

MidNode MidEdgeGeometry::onCurve(int a, int b, const Link& link) const {
  const ModelEdge& ed = model_.edges[link.edge];
  const double ta = a < b ? link.ta : link.tb, tb = a < b ? link.tb : link.ta;
  const Vec3 chordMid = 0.5 * (mesh_.nodes[a] + mesh_.nodes[b]);
  const double tm = 0.5 * (ta + tb);
  // The projection of the chord midpoint (near the arc-length midpoint), unless the
  // parameter midpoint's image is nearer the chord midpoint.
  double t = ed.curve->project(chordMid, tm, std::min(ta, tb), std::max(ta, tb));
  Vec3 p = edgePoint(model_, link.edge, t);
  const Vec3 pm = edgePoint(model_, link.edge, tm);
  if (!p.allFinite() || (pm.allFinite() && (pm - chordMid).norm() < (p - chordMid).norm())) {
    t = tm;
    p = pm;
  }
  NodeOn on;
  on.kind = NodeOn::Kind::Edge;
  on.entity = link.edge;
  on.t = t;
  if (!p.allFinite()) return {chordMid, on};
  return {p, on};
}

std::vector<MidEdgeGeometry::UvCandidate> MidEdgeGeometry::uvCandidates(int node, int face) const {
  const NodeOn& on = mesh_.nodeOn[node];
  std::vector<UvCandidate> out;
  auto pcurvesOn = [&](int e, auto&& use) {
    for (const PCurve& pc : model_.edges[e].pcurves)
      if (pc.face == face && pc.curve) use(pc);
  };
  switch (on.kind) {
    case NodeOn::Kind::Face:
      if (on.entity == face) out.push_back({on.uv, nullptr});
      break;
    case NodeOn::Kind::Edge:
      pcurvesOn(on.entity, [&](const PCurve& pc) { out.push_back({pc.curve->point(on.t), nullptr}); });
      break;
    case NodeOn::Kind::Vertex:
      for (int e : vertexEdges_[on.entity]) {
        const ModelEdge& ed = model_.edges[e];
        pcurvesOn(e, [&](const PCurve& pc) {
          if (ed.degenerate) {
            out.push_back({pc.curve->point(pc.t0), &pc});
            return;
          }
          if (ed.v0 == on.entity) out.push_back({pc.curve->point(pc.t0), nullptr});
          if (ed.v1 == on.entity) out.push_back({pc.curve->point(pc.t1), nullptr});
        });
      }
      break;
    case NodeOn::Kind::Solid:
      break;
  }
  return out;
}

bool MidEdgeGeometry::closestUvPair(int a, int b, int face, Vec2& ua, Vec2& ub) const {
  const ModelFace& f = model_.faces[face];
  const contour::PeriodicUv periodic(f.surface->domain(), f.uvBounds);
  // The point of a pole's pcurve nearest `uv` (uv's representative nearest the pcurve).
  auto onPole = [&](const PCurve& pc, const Vec2& uv) {
    const double tm = 0.5 * (pc.t0 + pc.t1);
    const Vec2 shift = periodic.shiftToward(uv, pc.curve->point(tm));
    const double t = pc.curve->project(uv + shift, tm, std::min(pc.t0, pc.t1), std::max(pc.t0, pc.t1));
    return Vec2(pc.curve->point(t) - shift);
  };
  std::vector<UvCandidate> ca = uvCandidates(a, face), cb = uvCandidates(b, face);
  // A node unknown on this face (not expected in a conforming mesh): project it.
  auto adopt = [&](std::vector<UvCandidate>& missing, int node, const std::vector<UvCandidate>& other) {
    if (!missing.empty()) return;
    const Vec2 start = other.empty() ? Vec2(0.5 * (f.uvBounds.lo + f.uvBounds.hi)) : other.front().uv;
    missing.push_back({f.surface->project(mesh_.nodes[node], start), nullptr});
  };
  adopt(ca, a, cb);
  adopt(cb, b, ca);

  double best = std::numeric_limits<double>::infinity();
  for (const UvCandidate& x : ca)
    for (const UvCandidate& y : cb) {
      if (x.pole && y.pole) continue;
      Vec2 p = x.uv, q = y.uv;
      if (x.pole) {
        p = onPole(*x.pole, q);
      } else if (y.pole) {
        q = onPole(*y.pole, p);
      } else {
        q += periodic.shiftToward(q, p);
      }
      const double d = (p - q).norm();
      if (d < best) {
        best = d;
        ua = p;
        ub = q;
      }
    }
  return std::isfinite(best);
}

MidNode MidEdgeGeometry::onSurface(int a, int b, int face) const {
  const Vec3 chordMid = 0.5 * (mesh_.nodes[a] + mesh_.nodes[b]);
  NodeOn on;
  on.kind = NodeOn::Kind::Face;
  on.entity = face;
  if (face < 0 || static_cast<std::size_t>(face) >= model_.faces.size() || !model_.faces[face].surface)
    throw MeshingError("order 2: an element lies on face " + std::to_string(face + 1) + ", which has no surface");
  const ModelFace& f = model_.faces[face];
  const ParametricSurface& s = *f.surface;
  Vec2 ua, ub;
  if (!closestUvPair(a, b, face, ua, ub)) {
    on.uv = s.project(chordMid, Vec2(0.5 * (f.uvBounds.lo + f.uvBounds.hi)));
    return {s.point(on.uv), on};
  }
  // Candidates: the (u, v) midpoint's image and the chord midpoint projected from it; where
  // both are far from the chord (a seam the domain does not declare periodic, say), the
  // projections from either end too. The one nearest the chord midpoint wins.
  const double limit = kMaxProjectionShift * (mesh_.nodes[b] - mesh_.nodes[a]).norm();
  Vec2 best(0, 0);
  double bestDistance = std::numeric_limits<double>::infinity();
  auto consider = [&](const Vec2& uv) {
    const Vec3 p = s.point(uv);
    const double d = (p - chordMid).norm();
    if (p.allFinite() && uv.allFinite() && d < bestDistance) {
      best = uv;
      bestDistance = d;
    }
  };
  const Vec2 uvMid = 0.5 * (ua + ub);
  consider(uvMid);
  consider(s.project(chordMid, uvMid));
  if (!(bestDistance <= limit)) {
    consider(s.project(chordMid, ua));
    consider(s.project(chordMid, ub));
  }
  if (!std::isfinite(bestDistance)) return {chordMid, on};
  on.uv = contour::PeriodicUv(s.domain(), f.uvBounds).intoBounds(best);
  return {s.point(best), on};
}

}  // namespace aniso
