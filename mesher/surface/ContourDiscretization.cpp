// discretizeEdges — thesis sec. 4.3, alg. 4.1, for every model edge of the meshed faces.
//
// For edge e with pcurves c_k on the meshed faces f_k (two on a seam face), the metric
// density along the edge is the pointwise maximum
//   ρ(t) = max_k |M_k(c_k(t)) c_k'(t)|,   M_k = M_s M_p of face f_k's control space,
// so that the discretization is fine enough for every adjacent face (alg. 4.1 steps 1, 4
// and 6 at once: all faces share the edge parameter t, OCCT's SameParameter). The number
// of segments is n = max(1, round(∫ρ)), raised by the rules below, and the nodes are placed
// at equal metric arc length (steps 2–3: the remainder of the last unit step spread over
// all segments). A degenerate edge (pole) is measured along its pcurve moved one mesh size
// into the face (see poleDensity), so the pole gets a ring of pieces for the face mesher
// to fan from, instead of the single piece its g_min-guarded length gives.
// With evenSegments (quad meshes) the nodes near a face's sharp corners are matched across
// the sliver there (contour/CuspNodes.h). Node creation order: vertex nodes (vertex
// order), then the inner nodes of every edge (edge order, increasing t).
//
// Segment-count rules, each needed for a valid boundary:
//  - a closed edge (v0 == v1) gets at least max(3, minSegmentsClosedEdge) segments (fewer
//    would repeat a node pair or collapse the edge);
//  - of several edges joining the same two vertices, at most one (the shortest) keeps a
//    single segment (two would give the same node pair twice);
//  - every loop of a meshed face has at least 3 segments (counting pole pieces);
//  - with evenSegments, odd counts are raised by one (alg. 4.1 step 7).
#include "mesher/surface/ContourDiscretization.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <tuple>

#include "mesher/core/Error.h"
#include "mesher/model/EdgePoint.h"
#include "mesher/surface/contour/CoincidentEdges.h"
#include "mesher/surface/contour/CornerParity.h"
#include "mesher/surface/contour/CuspNodes.h"
#include "mesher/surface/contour/VertexNearEdge.h"
#include "mesher/surface/contour/MetricArcLength.h"
#include "mesher/surface/contour/PeriodicUv.h"

namespace aniso {
namespace {

/// More segments than this on one edge means a broken size field, not a mesh request.
constexpr double kMaxSegmentsPerEdge = 1e7;
/// Fewest segments of a closed edge whatever the options say.
constexpr int kMinClosedSegments = 3;
/// Fewest segments of a loop.
constexpr int kMinLoopSegments = 3;
/// Small-feature floor, relative to the model's diagonal: vertices closer than this are one
/// node, CAD edges shorter collapse to it, and edges that close together are twins
/// (contour/CoincidentEdges.h). The general fuse of the assembly treats parts this close as
/// touching (its largest fuzzy value, cad/PrepareFragment.cpp's kFuzzyMaxRel); an element
/// this small against a part would be a sliver. Not with --quad (a collapsed edge would
/// leave its loops with an odd count).
constexpr double kSmallFeatureRel = 1e-6;

std::string edgeName(int e) { return "edge " + std::to_string(e + 1); }

/// What the density needs from one pcurve of the edge.
struct PCurveMetric {
  const ParametricCurve2d* curve = nullptr;
  const ControlSpace2d* cs = nullptr;
  contour::PeriodicUv periodic;
  /// Degenerate edges: the face's side of the pcurve, +1 left of c_p', −1 right, 0 unknown
  /// (both sides are measured).
  int inward = 0;
  Vec2 boundsSize{0, 0};
};

/// The side of pcurve k of edge e on which face f lies, from the edge's use in f's loops:
/// the face is on the left of the walking direction unless the face is reversed.
int inwardSide(const Model& model, int e, int k, int f) {
  const ModelFace& face = model.faces[f];
  for (const Loop& loop : face.loops)
    for (const EdgeUse& u : loop.uses)
      if (u.edge == e && u.pcurve == k) return (u.reversed ? -1 : 1) * (face.reversed ? -1 : 1);
  return 0;
}

/// Edges used in a loop of a meshed face (checking the references on the way).
std::vector<char> usedEdges(const Model& model, const std::vector<const ControlSpace2d*>& spaces) {
  std::vector<char> used(model.edges.size(), 0);
  for (std::size_t f = 0; f < model.faces.size(); ++f) {
    if (!spaces[f]) continue;
    for (const Loop& loop : model.faces[f].loops)
      for (const EdgeUse& u : loop.uses) {
        if (u.edge < 0 || static_cast<std::size_t>(u.edge) >= model.edges.size())
          throw MeshingError("face " + std::to_string(f + 1) + ": a loop refers to a missing edge");
        used[u.edge] = 1;
      }
  }
  return used;
}

/// The pcurves of edge e on meshed faces, with their control spaces.
std::vector<PCurveMetric> meshedPCurves(const Model& model, int e,
                                        const std::vector<const ControlSpace2d*>& spaces) {
  const ModelEdge& ed = model.edges[e];
  std::vector<PCurveMetric> out;
  for (std::size_t k = 0; k < ed.pcurves.size(); ++k) {
    const PCurve& pc = ed.pcurves[k];
    if (pc.face < 0 || static_cast<std::size_t>(pc.face) >= model.faces.size() || !spaces[pc.face]) continue;
    const ModelFace& face = model.faces[pc.face];
    if (!pc.curve || !face.surface)
      throw MeshingError(edgeName(e) + ": missing pcurve or surface on face " + std::to_string(pc.face + 1));
    const Box2 bounds = spaces[pc.face]->bounds();
    PCurveMetric m;
    m.curve = pc.curve.get();
    m.cs = spaces[pc.face];
    m.periodic = contour::PeriodicUv(face.surface->domain(), bounds);
    m.inward = ed.degenerate ? inwardSide(model, e, static_cast<int>(k), pc.face) : 0;
    m.boundsSize = bounds.size();
    out.push_back(m);
  }
  if (out.empty()) throw MeshingError(edgeName(e) + ": no pcurve on any meshed face that uses it");
  return out;
}

/// Metric density |M(c(t)) c'(t)| of one pcurve.
double pcurveDensity(const PCurveMetric& pc, const Vec2& uv, const Vec2& d1) {
  return (pc.cs->getMetric(pc.periodic.intoBounds(uv)).transformation() * d1).norm();
}

/// A degenerate edge (a pole) has no length in 3D and almost none in the metric (only the
/// g_min guard of M_p): split by that alone it would get one piece, and the face mesher
/// would then fan the pole from one or two nodes, folding the triangles around it in 3D.
/// It is measured instead along its pcurve moved one mesh size into the face (δ(t) =
/// 1/|M n| along the inward unit normal n, at most half the face's extent): the ring of
/// nodes around the pole, about 2π/h·h ≈ 6 pieces on a smooth pole whatever the size.
double poleDensity(const PCurveMetric& pc, const Vec2& uv, const Vec2& d1) {
  double rho = pcurveDensity(pc, uv, d1);
  const double speed = d1.norm();
  if (!(speed > 0) || !std::isfinite(speed)) return rho;
  const Vec2 left(-d1.y() / speed, d1.x() / speed);
  const Mat2 m = pc.cs->getMetric(pc.periodic.intoBounds(uv)).transformation();
  for (int side : {-1, 1}) {
    if (pc.inward != 0 && side != pc.inward) continue;
    const Vec2 n = side * left;
    const double extent = std::abs(n.x()) * pc.boundsSize.x() + std::abs(n.y()) * pc.boundsSize.y();
    const double delta = std::min(1 / (m * n).norm(), 0.5 * extent);
    if (!(delta > 0) || !std::isfinite(delta)) continue;
    rho = std::max(rho, pcurveDensity(pc, uv + delta * n, d1));
  }
  return rho;
}

/// Parameter range of the discretization: the edge's, along the first meshed pcurve for a
/// degenerate edge (which has no 3D curve).
std::array<double, 2> edgeRange(const Model& model, int e, const std::vector<const ControlSpace2d*>& spaces) {
  const ModelEdge& ed = model.edges[e];
  if (!ed.degenerate) return {ed.t0, ed.t1};
  for (const PCurve& pc : ed.pcurves)
    if (pc.face >= 0 && static_cast<std::size_t>(pc.face) < spaces.size() && spaces[pc.face]) return {pc.t0, pc.t1};
  return {ed.t0, ed.t1};
}

contour::MetricArcLength edgeArcLength(const Model& model, int e,
                                       const std::vector<const ControlSpace2d*>& spaces) {
  const std::vector<PCurveMetric> pcs = meshedPCurves(model, e, spaces);
  const bool pole = model.edges[e].degenerate;
  const auto density = [&pcs, pole](double t) {
    double rho = 0;
    for (const PCurveMetric& pc : pcs) {
      const Curve2dD2 d = pc.curve->d2(t);
      const double r = pole ? poleDensity(pc, d.p, d.d1) : pcurveDensity(pc, d.p, d.d1);
      if (!std::isfinite(r)) return r;  // reported by MetricArcLength
      rho = std::max(rho, r);
    }
    return rho;
  };
  const std::array<double, 2> range = edgeRange(model, e, spaces);
  try {
    return contour::MetricArcLength(density, range[0], range[1]);
  } catch (const MeshingError& err) {
    throw MeshingError(edgeName(e) + ": " + err.what());
  }
}

/// n = max(1, round(L)) and the closed-edge rule.
int basicCount(const ModelEdge& ed, int e, double length, const ContourOptions& options) {
  if (!(length <= kMaxSegmentsPerEdge)) {
    std::ostringstream s;
    s << edgeName(e) << ": metric length " << length << " asks for too many segments";
    throw MeshingError(s.str());
  }
  int n = std::max(1, static_cast<int>(std::lround(length)));
  if (!ed.degenerate && ed.v0 == ed.v1) n = std::max({n, kMinClosedSegments, options.minSegmentsClosedEdge});
  return n;
}

/// Of single-segment edges joining the same two vertices, only the shortest in the metric
/// (the lowest index on ties) keeps one segment; the others get two.
void separateParallelEdges(const Model& model, const std::vector<char>& used, const std::vector<double>& length,
                           const std::vector<int>& rep, const contour::EdgeTwins& twins, std::vector<int>& n) {
  struct Key {
    int lo, hi;
    double length;
    int edge;
    bool operator<(const Key& o) const { return std::tie(lo, hi, length, edge) < std::tie(o.lo, o.hi, o.length, o.edge); }
  };
  std::vector<Key> keys;
  for (std::size_t e = 0; e < model.edges.size(); ++e) {
    const ModelEdge& ed = model.edges[e];
    if (!used[e] || ed.degenerate || ed.v0 == ed.v1 || n[e] != 1 || twins.of[e] >= 0) continue;
    const int p = rep[ed.v0], q = rep[ed.v1];
    if (p == q) continue;  // collapsed to a point
    keys.push_back({std::min(p, q), std::max(p, q), length[e], static_cast<int>(e)});
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (keys[i].lo == keys[i - 1].lo && keys[i].hi == keys[i - 1].hi) n[keys[i].edge] = 2;
}

/// Every loop of a meshed face gets at least kMinLoopSegments segments: the longest edge of
/// a short loop (in metric length, degenerate edges last) is split further.
void fillShortLoops(const Model& model, const std::vector<const ControlSpace2d*>& spaces,
                    const std::vector<double>& length, std::vector<int>& n) {
  for (std::size_t f = 0; f < model.faces.size(); ++f) {
    if (!spaces[f]) continue;
    for (const Loop& loop : model.faces[f].loops) {
      if (loop.uses.empty()) continue;
      for (;;) {
        int total = 0;
        for (const EdgeUse& u : loop.uses) total += n[u.edge];
        if (total >= kMinLoopSegments) break;
        int best = loop.uses.front().edge;
        for (const EdgeUse& u : loop.uses) {
          const bool degU = model.edges[u.edge].degenerate, degB = model.edges[best].degenerate;
          if ((degB && !degU) || (degU == degB && length[u.edge] > length[best])) best = u.edge;
        }
        ++n[best];
      }
    }
  }
}

std::vector<int> segmentCounts(const Model& model, const std::vector<const ControlSpace2d*>& spaces,
                               const std::vector<char>& used, const std::vector<double>& length,
                               const std::vector<int>& rep, const contour::EdgeTwins& twins,
                               const ContourOptions& options) {
  std::vector<int> n(model.edges.size(), 0);
  for (std::size_t e = 0; e < model.edges.size(); ++e)
    if (used[e]) n[e] = basicCount(model.edges[e], static_cast<int>(e), length[e], options);
  separateParallelEdges(model, used, length, rep, twins, n);
  fillShortLoops(model, spaces, length, n);
  if (options.evenSegments) {
    for (int& k : n)
      if (k % 2) ++k;
    contour::makeCornerParity(model, spaces, used, n);
  }
  // twins share their nodes: the larger count of the two (two even counts stay even)
  for (std::size_t e = 0; e < n.size(); ++e)
    if (twins.of[e] >= 0) n[e] = n[twins.of[e]] = std::max(n[e], n[twins.of[e]]);
  for (std::size_t e = 0; e < n.size(); ++e)
    if (twins.of[e] >= 0) n[e] = n[twins.of[e]];
  for (std::size_t e = 0; e < n.size(); ++e)  // one node: its two ends are it
    if (used[e] && contour::collapsedEdge(model, static_cast<int>(e), rep)) n[e] = 1;
  return n;
}

void checkVertex(const Model& model, int v, int e) {
  if (v < 0 || static_cast<std::size_t>(v) >= model.vertices.size())
    throw MeshingError(edgeName(e) + ": vertex reference out of range");
}

/// The nodes of edge e at parameters t (n + 1 of them, ends included).
EdgeDiscretization placeNodes(const Model& model, int e, std::vector<double> t, const std::vector<int>& vertexNodes,
                              SurfaceMesh& mesh) {
  const ModelEdge& ed = model.edges[e];
  const int n = static_cast<int>(t.size()) - 1;
  EdgeDiscretization d;
  d.t = std::move(t);
  for (std::size_t i = 1; i < d.t.size(); ++i)
    if (!(d.t[i] > d.t[i - 1]))
      throw MeshingError(edgeName(e) + ": the metric arc length cannot be inverted (parameters do not increase)");
  d.nodes.resize(d.t.size());
  d.nodes.front() = vertexNodes[ed.v0];
  d.nodes.back() = vertexNodes[ed.v1];
  for (int i = 1; i < n; ++i) {
    if (ed.degenerate) {
      d.nodes[i] = vertexNodes[ed.v0];
      continue;
    }
    const Vec3 p = edgePoint(model, e, d.t[i]);
    if (!p.allFinite()) throw MeshingError(edgeName(e) + ": the 3D curve cannot be evaluated at t = " + std::to_string(d.t[i]));
    NodeOn on;
    on.kind = NodeOn::Kind::Edge;
    on.entity = e;
    on.t = d.t[i];
    d.nodes[i] = mesh.addNode(p, on);
  }
  return d;
}

/// Edge e, twin of edge a (CoincidentEdges.h): a's nodes, at e's own parameters (the
/// nearest points of e's curve, which must increase along e).
EdgeDiscretization twinNodes(const Model& model, int e, int a, bool reversed, const EdgeDiscretization& da,
                             const SurfaceMesh& mesh) {
  const ModelEdge& ed = model.edges[e];
  EdgeDiscretization d;
  d.nodes = da.nodes;
  if (reversed) std::reverse(d.nodes.begin(), d.nodes.end());
  const std::size_t n = d.nodes.size();
  d.t.resize(n);
  d.t.front() = ed.t0;
  d.t.back() = ed.t1;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double guess = ed.t0 + (ed.t1 - ed.t0) * static_cast<double>(i) / static_cast<double>(n - 1);
    d.t[i] = ed.curve->project(mesh.nodes[d.nodes[i]], guess, ed.t0, ed.t1);
    if (!(d.t[i] > d.t[i - 1]))
      throw MeshingError(edgeName(e) + " lies on edge " + std::to_string(a + 1) +
                         " but its curve runs differently: the two cannot share their nodes");
  }
  if (n > 1 && !(d.t[n - 1] > d.t[n - 2]))
    throw MeshingError(edgeName(e) + " lies on edge " + std::to_string(a + 1) +
                       " but its curve runs differently: the two cannot share their nodes");
  return d;
}

/// Edge e on its twin's nodes (CoincidentEdges.h) or, for an edge without a twin or one
/// whose curve cannot take its twin's nodes in order (a parameterization running back and
/// forth), on its own nodes at `t`.
EdgeDiscretization placeTwinOrOwn(const Model& model, int e, const contour::EdgeTwins& twins,
                                  const std::vector<EdgeDiscretization>& done, std::vector<double> t,
                                  const std::vector<int>& vertexNodes, SurfaceMesh& mesh) {
  const int a = twins.of[e];
  if (a >= 0) {
    try {
      return twinNodes(model, e, a, twins.reversed[e], done[a], mesh);
    } catch (const MeshingError&) {
      // its own nodes below
    }
  }
  return placeNodes(model, e, std::move(t), vertexNodes, mesh);
}

}  // namespace

std::vector<EdgeDiscretization> discretizeEdges(const Model& model,
                                                const std::vector<const ControlSpace2d*>& faceSpaces,
                                                const ContourOptions& options, SurfaceMesh& mesh) {
  if (faceSpaces.size() != model.faces.size())
    throw MeshingError("contour discretization: " + std::to_string(faceSpaces.size()) + " control spaces for " +
                       std::to_string(model.faces.size()) + " faces");
  const std::vector<char> used = usedEdges(model, faceSpaces);
  const int ne = static_cast<int>(model.edges.size());

  std::vector<contour::MetricArcLength> arcs;
  std::vector<int> arcOf(ne, -1);
  std::vector<double> length(ne, 0.0);
  for (int e = 0; e < ne; ++e) {
    if (!used[e]) continue;
    try {
      const ModelEdge& ed = model.edges[e];
      checkVertex(model, ed.v0, e);
      checkVertex(model, ed.v1, e);
      if (ed.degenerate ? ed.v0 != ed.v1 : !ed.curve)
        throw MeshingError(edgeName(e) + (ed.degenerate ? ": degenerate edge with two vertices" : ": no 3D curve"));
      arcOf[e] = static_cast<int>(arcs.size());
      arcs.push_back(edgeArcLength(model, e, faceSpaces));
      length[e] = arcs.back().total();
    } catch (const MeshingError& err) {
      throw EntityError(EntityKind::Edge, e, err.what());
    }
  }
  // after the checks above: every used edge has valid vertices
  const double floor = options.evenSegments ? 0.0 : kSmallFeatureRel * model.diagonal();
  const std::vector<int> rep = contour::coincidentVertices(model, used, floor);
  const contour::EdgeTwins twins = contour::coincidentEdges(model, used, rep, floor);
  const std::vector<int> n = segmentCounts(model, faceSpaces, used, length, rep, twins, options);

  // Vertex nodes first, in vertex order.
  std::vector<char> vertexUsed(model.vertices.size(), 0);
  for (int e = 0; e < ne; ++e)
    if (used[e]) vertexUsed[rep[model.edges[e].v0]] = vertexUsed[rep[model.edges[e].v1]] = 1;
  std::vector<int> vertexNodes(model.vertices.size(), -1);
  for (std::size_t v = 0; v < model.vertices.size(); ++v) {
    if (!vertexUsed[v] || rep[v] != static_cast<int>(v)) continue;
    NodeOn on;
    on.kind = NodeOn::Kind::Vertex;
    on.entity = static_cast<int>(v);
    vertexNodes[v] = mesh.addNode(model.vertices[v].p, on);
  }
  for (std::size_t v = 0; v < model.vertices.size(); ++v) vertexNodes[v] = vertexNodes[rep[v]];

  std::vector<std::vector<double>> params(ne);
  for (int e = 0; e < ne; ++e)
    if (used[e]) params[e] = arcs[arcOf[e]].equalSpacing(n[e]);
  if (options.evenSegments)
    contour::matchCuspNodes(model, faceSpaces, params);
  else  // (a node more would break the even counts quads need)
    contour::addNodesNearVertices(model, faceSpaces, params);
  for (int e = 0; e < ne; ++e)
    if (used[e] && contour::collapsedEdge(model, e, rep)) params[e] = {model.edges[e].t0, model.edges[e].t1};
  std::vector<EdgeDiscretization> out(ne);
  for (int e = 0; e < ne; ++e) {
    if (!used[e]) continue;
    try {
      out[e] = placeTwinOrOwn(model, e, twins, out, std::move(params[e]), vertexNodes, mesh);
    } catch (const MeshingError& err) {
      throw EntityError(EntityKind::Edge, e, err.what());
    }
  }
  return out;
}

}  // namespace aniso
