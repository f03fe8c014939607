// faceBoundary — the boundary loops of one face in (u, v) from the edge discretizations
// (thesis sec. 4.3, alg. 4.1 step 6: the contour nodes in the parametric space of each
// adjacent patch).
//
// Each use contributes the nodes of its edge in walking order with uv = c_p(t) on the
// use's pcurve (on a seam, the pcurve of that side). The edge's 3D curve is the master of
// the inner nodes' positions; where p(c_p(t)) is further from the node than the CAD
// tolerances allow (a pcurve not parameterized like its 3D curve, SameParameter not
// holding: up to 30 model units on a 7e-4 tolerance in submarine.stp), the node is
// projected onto the pcurve's image instead (step 6's projection), keeping the parameters
// increasing along the edge.
// Consecutive uses share their vertex node. On a periodic surface each use is moved by whole
// periods next to the previous one, and afterwards each loop as a whole so that it overlaps
// the face's parametric bounds (the outer loop) or the outer loop (the holes) as much as
// possible: the control space covers the face's stored bounds. At a junction whose two
// pcurve ends meet within kLoopGapRatio of the face's parametric extent the vertex node is
// emitted once, at their midpoint. A wider junction is meshed only when the straight (u, v)
// segment between the ends stays, in 3D, within the CAD tolerance of the vertex (a CAD
// system that dropped a short edge and widened the vertex's tolerance over it): the segment
// is then a pole of the face's boundary, the vertex node repeated along it at the spacing
// of the neighbouring boundary nodes, as on a degenerate edge. A junction whose ends only
// are one point in 3D is closed at its midpoint up to kLoopGapEndsWithinTolerance of the
// extent. Any other junction is an error. Copies of one node that differ by round-off only
// (a hole touching the outer loop at a vertex), or, at a vertex, by less than its CAD
// tolerance (edges a fuse embedded in the face, whose pcurves end up to that tolerance
// apart), are given one (u, v).
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>

#include "mesher/core/Error.h"
#include "mesher/geometry/CurveOnSurface3d.h"
#include "mesher/surface/ContourDiscretization.h"
#include "mesher/surface/contour/PeriodicUv.h"

namespace aniso {
namespace {

/// Largest (u, v) gap between consecutive uses, relative to the diagonal of the face's
/// parametric extent (the same order as Model::validate's kUvGapRatio).
constexpr double kLoopGapRatio = 1e-2;
/// A wider gap is bridged as a pole when the bridge's image lies within the CAD tolerance
/// of the vertex (kMissFactor × the largest tolerance of the vertex, the two edges and the
/// face, plus kMissRelative × the model size), tested at this many points along it.
constexpr int kBridgeSamples = 16;
/// Most copies of the vertex node along one bridge.
constexpr int kMaxBridgeCopies = 64;
/// A gap whose bridge strays but whose two ends are one point in 3D within that tolerance
/// is still closed at its midpoint up to this share of the extent.
constexpr double kLoopGapEndsWithinTolerance = 0.1;
/// Copies of one node closer than this (relative to the parametric extent) are made equal:
/// a hole touching the outer loop at a vertex, the two pcurve ends differing by round-off.
constexpr double kSnapRatio = 1e-9;
/// An inner edge node whose pcurve point misses it in 3D by more than kMissFactor × the
/// CAD tolerance (edge or face) plus kMissRelative × the model size is projected.
constexpr double kMissFactor = 2;
constexpr double kMissRelative = 1e-9;

struct UseNodes {
  std::vector<Vec2> uv;
  std::vector<int> node;
};

struct Junction {
  double gap = 0;
  int from = -1, to = -1;  ///< edges (0-based) of the two uses
  bool bridged = false;     ///< wide, but its straight bridge is one point in 3D: a pole
  bool endsClosedIn3d = false;  ///< the two ends are one point within the CAD tolerance
};

std::string where(int face, std::size_t loop) {
  return "face " + std::to_string(face + 1) + " loop " + std::to_string(loop + 1);
}

/// Parameters on the pcurve for the inner nodes of edge `e` whose 3D position p(c_p(t))
/// misses by more than `tol`: the nearest point of p∘c_p to the node, searched after the
/// previous node's parameter. Unchanged when the projection does not help or would not keep
/// the parameters strictly increasing.
std::vector<double> projectedParameters(const ModelEdge& ed, const PCurve& pc, const SurfacePtr& surface,
                                        const EdgeDiscretization& d, const SurfaceMesh& mesh, double tol) {
  std::vector<double> t = d.t;
  if (ed.degenerate || t.size() < 3) return t;
  const ParametricSurface& s = *surface;
  std::unique_ptr<CurveOnSurface3d> image;
  bool changed = false;
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    const Vec3& x = mesh.nodes[d.nodes[i]];
    const double miss = (s.point(pc.curve->point(t[i])) - x).norm();
    if (!(miss > tol)) continue;
    if (!image) image = std::make_unique<CurveOnSurface3d>(surface, pc.curve);
    const double lo = t[i - 1], hi = t.back();
    const double tp = image->project(x, std::clamp(t[i], lo, hi), lo, hi);
    if (tp > lo && tp < hi && (image->point(tp) - x).norm() < miss) {
      t[i] = tp;
      changed = true;
    }
  }
  if (!changed) return t;
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1])) return d.t;
  return t;
}

UseNodes useNodes(const Model& model, int face, std::size_t loop, const EdgeUse& use,
                  const std::vector<EdgeDiscretization>& edges, const SurfaceMesh& mesh) {
  const std::string name = where(face, loop) + ": edge " + std::to_string(use.edge + 1);
  if (use.edge < 0 || static_cast<std::size_t>(use.edge) >= model.edges.size() ||
      static_cast<std::size_t>(use.edge) >= edges.size())
    throw MeshingError(where(face, loop) + ": edge reference out of range");
  const ModelEdge& ed = model.edges[use.edge];
  const EdgeDiscretization& d = edges[use.edge];
  if (d.nodes.size() < 2 || d.t.size() != d.nodes.size())
    throw MeshingError(name + " has not been discretized");
  for (int n : d.nodes)
    if (n < 0 || static_cast<std::size_t>(n) >= mesh.nodes.size())
      throw MeshingError(name + ": node " + std::to_string(n) + " is not in the surface mesh");
  if (use.pcurve < 0 || static_cast<std::size_t>(use.pcurve) >= ed.pcurves.size() ||
      ed.pcurves[use.pcurve].face != face || !ed.pcurves[use.pcurve].curve)
    throw MeshingError(name + " has no pcurve on the face for this use");
  const PCurve& pc = ed.pcurves[use.pcurve];
  const ModelFace& f = model.faces[face];
  const double tol = kMissFactor * std::max(ed.tolerance, f.tolerance) + kMissRelative * model.diagonal();
  const std::vector<double> ts = projectedParameters(ed, pc, f.surface, d, mesh, tol);
  UseNodes out;
  out.uv.reserve(ts.size());
  for (double t : ts) {
    const Vec2 p = pc.curve->point(t);
    if (!p.allFinite()) throw MeshingError(name + ": the pcurve cannot be evaluated at t = " + std::to_string(t));
    out.uv.push_back(p);
  }
  out.node = d.nodes;
  if (use.reversed) {
    std::reverse(out.uv.begin(), out.uv.end());
    std::reverse(out.node.begin(), out.node.end());
  }
  return out;
}

/// True when the straight (u, v) segment from `a` to `b` lies, in 3D, within `tol` of `x`.
bool bridgeWithin(const ParametricSurface& s, const Vec2& a, const Vec2& b, const Vec3& x, double tol) {
  for (int i = 0; i <= kBridgeSamples; ++i) {
    const double w = static_cast<double>(i) / kBridgeSamples;
    if (!((s.point((1 - w) * a + w * b) - x).norm() <= tol)) return false;
  }
  return true;
}

/// The loop's nodes chained in (u, v); `junctions` receives the gap at every junction.
/// `extent` is the face's parametric extent (kLoopGapRatio); +inf: no bridge, every vertex
/// at its midpoint.
std::vector<BoundaryNode> chainLoop(const Model& model, int face, std::size_t l, const contour::PeriodicUv& periodic,
                                    const std::vector<EdgeDiscretization>& edges, const SurfaceMesh& mesh,
                                    double extent, std::vector<Junction>& junctions) {
  const Loop& loop = model.faces[face].loops[l];
  if (loop.uses.empty()) throw MeshingError(where(face, l) + ": empty loop");
  std::vector<BoundaryNode> out;
  Vec2 end(0, 0);
  int endNode = -1, endEdge = -1;
  // The junction of the previous use's end with `start` (the next use's first node, whose
  // neighbour along that use is `next`): the vertex at the midpoint, or a bridge of copies
  // of it appended to `out` from `end` up to, not including, `start`.
  const auto join = [&](Vec2& start, const Vec2& next, int startNode, int startEdge) {
    if (startNode != endNode) {
      std::ostringstream s;
      s << where(face, l) << ": edge " << endEdge + 1 << " ends at node " << endNode << " but edge " << startEdge + 1
        << " starts at node " << startNode << " (the loop does not chain)";
      throw MeshingError(s.str());
    }
    const ModelFace& f = model.faces[face];
    const ModelEdge& ea = model.edges[endEdge];
    const ModelEdge& eb = model.edges[startEdge];
    const NodeOn& on = mesh.nodeOn[static_cast<std::size_t>(startNode)];
    const double vertexTol = on.kind == NodeOn::Kind::Vertex ? model.vertices[static_cast<std::size_t>(on.entity)].tolerance : 0.0;
    const double tol = kMissFactor * std::max({ea.tolerance, eb.tolerance, f.tolerance, vertexTol}) +
                       kMissRelative * model.diagonal();
    const double gap = (start - end).norm();
    const Vec3& vertex = mesh.nodes[static_cast<std::size_t>(startNode)];
    const bool bridged = !(gap <= kLoopGapRatio * extent) && bridgeWithin(*f.surface, end, start, vertex, tol);
    const bool endsClosed = (f.surface->point(start) - f.surface->point(end)).norm() <= tol;
    junctions.push_back({gap, endEdge, startEdge, bridged, endsClosed});
    if (!bridged) {
      start = 0.5 * (start + end);
      return;
    }
    const Vec2 before = out.empty() ? end : out.back().uv;
    const double spacing = 0.5 * ((end - before).norm() + (next - start).norm());
    const int copies = std::clamp(static_cast<int>(std::ceil(gap / std::max(spacing, 1e-300))), 1, kMaxBridgeCopies);
    for (int i = 0; i < copies; ++i)
      out.push_back({end + (start - end) * (static_cast<double>(i) / copies), startNode, vertex});
  };
  for (std::size_t k = 0; k < loop.uses.size(); ++k) {
    UseNodes un = useNodes(model, face, l, loop.uses[k], edges, mesh);
    if (k > 0) {
      const Vec2 shift = periodic.shiftToward(un.uv.front(), end);
      for (Vec2& p : un.uv) p += shift;
      join(un.uv.front(), un.uv[1], un.node.front(), loop.uses[k].edge);
    }
    for (std::size_t i = 0; i + 1 < un.uv.size(); ++i) out.push_back({un.uv[i], un.node[i]});
    end = un.uv.back();
    endNode = un.node.back();
    endEdge = loop.uses[k].edge;
  }
  const Vec2 next = out.size() > 1 ? out[1].uv : out.front().uv;
  join(out.front().uv, next, out.front().node, loop.uses.front().edge);
  return out;
}

Box2 boxOf(const std::vector<BoundaryNode>& loop) {
  Box2 b;
  for (const BoundaryNode& n : loop) b.add(n.uv);
  return b;
}

/// Moves the loop by whole periods so that its box overlaps `ref` most (no move on ties).
void alignToBox(std::vector<BoundaryNode>& loop, const Box2& ref, const Vec2& period) {
  if (ref.empty()) return;
  const Box2 box = boxOf(loop);
  Vec2 shift(0, 0);
  for (int i = 0; i < 2; ++i) {
    const double p = period[i];
    if (!(p > 0)) continue;
    const auto overlap = [&](double k) {
      return std::min(box.hi[i] + k * p, ref.hi[i]) - std::max(box.lo[i] + k * p, ref.lo[i]);
    };
    const double k0 = std::round((0.5 * (ref.lo[i] + ref.hi[i]) - 0.5 * (box.lo[i] + box.hi[i])) / p);
    double best = 0, bestOverlap = overlap(0);
    for (double k : {k0 - 1, k0, k0 + 1}) {
      const double o = overlap(k);
      if (o > bestOverlap + 1e-12 * p) {
        best = k;
        bestOverlap = o;
      }
    }
    shift[i] = best * p;
  }
  for (BoundaryNode& n : loop) n.uv += shift;
}

/// Gives every node the same (u, v) wherever it occurs within max(`tol`, nodeTol(node, uv))
/// of its first copy (nodeTol: a vertex's CAD tolerance in (u, v)), so that one point is one
/// point for the face mesher; copies next to each other in a loop, or made by a bridge, are
/// a pole and move only within `tol`.
void snapCopies(std::vector<std::vector<BoundaryNode>>& loops, double tol,
                const std::function<double(int, const Vec2&)>& nodeTol) {
  std::vector<std::array<int, 3>> refs;  // (node, loop, index)
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (std::size_t i = 0; i < loops[l].size(); ++i)
      refs.push_back({loops[l][i].node, static_cast<int>(l), static_cast<int>(i)});
  std::sort(refs.begin(), refs.end());
  for (std::size_t a = 0; a < refs.size(); ++a) {
    const BoundaryNode& first = loops[refs[a][1]][refs[a][2]];
    double within = -1;  // the node's own tolerance, asked only when it has copies
    for (std::size_t b = a + 1; b < refs.size() && refs[b][0] == refs[a][0]; ++b) {
      BoundaryNode& other = loops[refs[b][1]][refs[b][2]];
      // consecutive copies are a short pole of the loop (a degenerate edge), as are those a
      // bridge made (`at` set): only round-off is taken off them
      const auto size = static_cast<int>(loops[refs[a][1]].size());
      const int step = (refs[b][2] - refs[a][2] + size) % size;
      const bool pole = !std::isnan(other.at.x()) || !std::isnan(first.at.x()) ||
                        (refs[b][1] == refs[a][1] && (step == 1 || step == size - 1));
      if (!pole && within < 0) within = std::max(tol, nodeTol(first.node, first.uv));
      if ((other.uv - first.uv).norm() <= (pole ? tol : within)) other.uv = first.uv;
    }
  }
}

double extentDiagonal(const ModelFace& f, const std::vector<std::vector<BoundaryNode>>& loops) {
  const double d = f.uvBounds.diagonal();
  if (std::isfinite(d) && d > 0) return d;
  Box2 b;
  for (const auto& loop : loops) b.add(boxOf(loop));
  return b.diagonal();
}

}  // namespace

FaceBoundary faceBoundary(const Model& model, int face, const std::vector<EdgeDiscretization>& edges,
                          const SurfaceMesh& mesh) {
  if (face < 0 || static_cast<std::size_t>(face) >= model.faces.size())
    throw MeshingError("face " + std::to_string(face + 1) + " does not exist");
  const ModelFace& f = model.faces[face];
  if (!f.surface) throw MeshingError("face " + std::to_string(face + 1) + ": no surface");
  const contour::PeriodicUv periodic(f.surface->domain(), f.uvBounds);

  FaceBoundary out;
  out.face = face;
  std::vector<std::vector<Junction>> junctions(f.loops.size());
  const auto chainAll = [&](double extent) {
    out.loops.clear();
    for (std::size_t l = 0; l < f.loops.size(); ++l) {
      junctions[l].clear();
      out.loops.push_back(chainLoop(model, face, l, periodic, edges, mesh, extent, junctions[l]));
    }
  };
  double extent = f.uvBounds.diagonal();
  if (!(std::isfinite(extent) && extent > 0)) {  // no stored bounds: the loops' own box
    chainAll(std::numeric_limits<double>::infinity());
    extent = extentDiagonal(f, out.loops);
  }
  chainAll(extent);
  for (std::size_t l = 0; l < junctions.size(); ++l)
    for (const Junction& j : junctions[l])
      if (!(j.gap <= kLoopGapRatio * extent) && !j.bridged &&
          !(j.endsClosedIn3d && j.gap <= kLoopGapEndsWithinTolerance * extent)) {
        std::ostringstream s;
        s << where(face, l) << ": edges " << j.from + 1 << " and " << j.to + 1 << " do not meet in (u,v): gap " << j.gap
          << " for a parametric extent of " << extent << " (the loop is not closed)";
        throw MeshingError(s.str());
      }

  for (std::size_t l = 0; l < out.loops.size(); ++l)
    alignToBox(out.loops[l], l == 0 ? f.uvBounds : boxOf(out.loops[0]), periodic.period());
  // a vertex's copies whose (u, v) differ by less than its CAD tolerance are one point: the
  // tolerance over the larger of |p_u|, |p_v| (the smaller (u, v) distance: a pole's copies,
  // a period apart, never come that close)
  const auto vertexUvTolerance = [&](int node, const Vec2& uv) {
    const NodeOn& on = mesh.nodeOn[static_cast<std::size_t>(node)];
    if (on.kind != NodeOn::Kind::Vertex) return 0.0;
    const double tol3d = kMissFactor * std::max(model.vertices[static_cast<std::size_t>(on.entity)].tolerance, f.tolerance);
    const SurfaceD1 d = f.surface->d1(uv);
    const double scale = std::max(d.pu.norm(), d.pv.norm());
    return scale > 0 && std::isfinite(scale) ? tol3d / scale : 0.0;
  };
  snapCopies(out.loops, kSnapRatio * extent, vertexUvTolerance);
  if (f.reversed)
    for (auto& loop : out.loops) std::reverse(loop.begin(), loop.end());
  return out;
}

}  // namespace aniso
