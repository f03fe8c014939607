#include "mesher/delaunay/InsertPoint.h"

#include "mesher/core/Error.h"
#include "mesher/delaunay/PlaneTransform.h"
#include "mesher/delaunay/Workspace2d.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::del2d {
namespace {

constexpr std::uint8_t kIn = Triangulation2d::kMarkA;       // in the cavity
constexpr std::uint8_t kOut = Triangulation2d::kMarkB;      // tested or dropped: not in it
constexpr std::uint8_t kReached = Triangulation2d::kMarkC;  // reconnect() scratch

void clearMarks(Triangulation2d& tri, Workspace2d& ws) {
  for (TriId t : ws.cavity) tri.clearMark(t, kIn);
  for (TriId t : ws.tested) tri.clearMark(t, kOut);
}

/// The empty-circumcircle test on M·x (sec. 4.2.1), devirtualised for the hot path.
class MetricConflict final : public ConflictTest {
 public:
  MetricConflict(const PlaneTransform& tr, const Vec2& p) : tr_(tr), mp_(tr.apply(p)) {}
  bool inConflict(const Triangulation2d& tri, TriId t) const override {
    const std::uint32_t* v = tri.triVertices(t);
    return tr_.inCircle(tri.point(VertexId(v[0])), tri.point(VertexId(v[1])), tri.point(VertexId(v[2])), mp_) > 0;
  }

 private:
  const PlaneTransform& tr_;
  Vec2 mp_;
};

/// Grows the cavity from the triangles already in ws.cavity (marked kIn) through
/// unconstrained edges into the triangles in conflict.
template <class Test>
void growCavity(Triangulation2d& tri, Workspace2d& ws, const Test& test, std::size_t& tests) {
  ws.stack.assign(ws.cavity.begin(), ws.cavity.end());
  while (!ws.stack.empty()) {
    const TriId t = ws.stack.back();
    ws.stack.pop_back();
    const std::uint32_t* tn = tri.triNeighbours(t);
    for (int i = 0; i < 3; ++i) {
      const TriId u(tn[i]);
      if (!u.valid() || tri.isConstrained(t, i) || (tri.flags(u) & (kIn | kOut))) continue;
      ++tests;
      if (test.inConflict(tri, u)) {
        tri.setMark(u, kIn);
        ws.cavity.push_back(u);
        ws.stack.push_back(u);
      } else {
        tri.setMark(u, kOut);
        ws.tested.push_back(u);
      }
    }
  }
}

/// The edges of cavity triangles whose other side is not in the cavity (or constrained).
void collectBoundary(const Triangulation2d& tri, Workspace2d& ws) {
  ws.boundary.clear();
  for (TriId t : ws.cavity) {
    const std::uint32_t* tv = tri.triVertices(t);
    const std::uint32_t* tn = tri.triNeighbours(t);
    for (int i = 0; i < 3; ++i) {
      const TriId u(tn[i]);
      const bool c = tri.isConstrained(t, i);
      if (!c && u.valid() && tri.hasMark(u, kIn)) continue;
      CavityEdge e;
      e.a = VertexId(tv[kNext[i]]);
      e.b = VertexId(tv[kPrev[i]]);
      e.owner = t;
      e.ownerEdge = i;
      e.outside = u;
      e.outsideEdge = u.valid() ? tri.neighbourIndex(u, t) : -1;
      e.constrained = c;
      ws.boundary.push_back(e);
    }
  }
}

/// Drops t from the cavity, then everything no longer connected to `root` through
/// unconstrained edges inside the cavity. Returns the number of triangles dropped.
std::size_t dropAndReconnect(Triangulation2d& tri, Workspace2d& ws, TriId t, TriId root) {
  tri.clearMark(t, kIn);
  tri.setMark(t, kOut);
  ws.tested.push_back(t);
  ws.stack.clear();
  ws.stack.push_back(root);
  tri.setMark(root, kReached);
  std::size_t reached = 0;
  while (!ws.stack.empty()) {
    const TriId s = ws.stack.back();
    ws.stack.pop_back();
    ++reached;
    for (int i = 0; i < 3; ++i) {
      const TriId u = tri.neighbour(s, i);
      if (!u.valid() || tri.isConstrained(s, i)) continue;
      if (tri.hasMark(u, kIn) && !tri.hasMark(u, kReached)) {
        tri.setMark(u, kReached);
        ws.stack.push_back(u);
      }
    }
  }
  std::size_t dropped = 0, k = 0;
  for (TriId c : ws.cavity) {
    if (tri.hasMark(c, kReached)) {
      tri.clearMark(c, kReached);
      ws.cavity[k++] = c;
    } else if (tri.hasMark(c, kIn)) {
      tri.clearMark(c, kIn);
      tri.setMark(c, kOut);
      ws.tested.push_back(c);
      ++dropped;
    } else {
      ++dropped;  // t itself
    }
  }
  ws.cavity.resize(k);
  (void)reached;
  return dropped;
}

/// A cavity triangle other than root incident to a vertex of the cavity that is not on
/// its boundary (it would be lost by the retriangulation), or an invalid id.
TriId triangleAroundInteriorVertex(const Triangulation2d& tri, Workspace2d& ws, TriId root) {
  if (ws.vstamp.size() < tri.numVertices()) ws.vstamp.resize(tri.numVertices(), 0);
  if (++ws.stamp == 0) {
    std::fill(ws.vstamp.begin(), ws.vstamp.end(), 0u);
    ws.stamp = 1;
  }
  for (const CavityEdge& e : ws.boundary) ws.vstamp[e.a.index] = ws.stamp;
  for (TriId t : ws.cavity) {
    const std::uint32_t* tv = tri.triVertices(t);
    for (int i = 0; i < 3; ++i) {
      if (ws.vstamp[tv[i]] == ws.stamp) continue;
      if (t != root) return t;
      // The root touches the interior vertex: take another triangle around it.
      for (TriId s : ws.cavity)
        if (s != root && tri.localIndex(s, VertexId(tv[i])) >= 0) return s;
    }
  }
  return TriId();
}

/// Star-shape pruning: until every boundary edge sees p strictly on its left and no
/// vertex is strictly inside. False when the root itself would have to go.
bool makeStarShaped(Triangulation2d& tri, Workspace2d& ws, const Vec2& p, TriId root, std::size_t& pruned,
                    const NewTriangleTest* extra) {
  for (;;) {
    collectBoundary(tri, ws);
    TriId drop;
    for (const CavityEdge& e : ws.boundary)
      if (predicates::orient2d(tri.coords(e.a), tri.coords(e.b), p.data()) <= 0 ||
          (extra && !extra->accept(tri, e.a, e.b))) {
        drop = e.owner;
        break;
      }
    if (!drop.valid() && ws.boundary.size() != ws.cavity.size() + 2) {
      drop = triangleAroundInteriorVertex(tri, ws, root);
      if (!drop.valid()) return false;  // cannot happen on a valid triangulation
    }
    if (!drop.valid()) return true;
    if (drop == root) return false;
    pruned += dropAndReconnect(tri, ws, drop, root);
  }
}

template <class Test>
InsertPlan makePlan(Triangulation2d& tri, const Vec2& p, const Test& test, TriId start,
                    const NewTriangleTest* extra) {
  InsertPlan plan;
  plan.point = p;
  plan.revision = tri.revision();
  plan.workspace = &tri.workspace();
  plan.location = locate(tri, p, start);
  const LocateResult& loc = plan.location;
  if (loc.where == Location::Outside) {
    plan.status = InsertStatus::Outside;
    return plan;
  }
  if (loc.where == Location::OnVertex) {
    plan.status = InsertStatus::Duplicate;
    plan.duplicate = tri.vertex(loc.tri, loc.index);
    return plan;
  }
  Workspace2d& ws = tri.workspace();
  ws.cavity.clear();
  ws.tested.clear();
  // The containing triangle, and on an unconstrained edge also the one across it, are in
  // the cavity without testing (p is on their closure).
  ws.cavity.push_back(loc.tri);
  tri.setMark(loc.tri, kIn);
  if (loc.where == Location::OnEdge && !tri.isConstrained(loc.tri, loc.index)) {
    const TriId u = tri.neighbour(loc.tri, loc.index);
    if (u.valid()) {
      ws.cavity.push_back(u);
      tri.setMark(u, kIn);
    }
  }
  growCavity(tri, ws, test, plan.incircleTests);
  const bool ok = makeStarShaped(tri, ws, p, loc.tri, plan.pruned, extra);
  clearMarks(tri, ws);
  if (!ok) {
    plan.reason = RefuseReason::NotStarShaped;
    return plan;
  }
  plan.status = InsertStatus::Inserted;
  return plan;
}

}  // namespace

InsertPlan planInsertion(Triangulation2d& tri, const Vec2& p, const Mat2& m, TriId start,
                         const NewTriangleTest* extra) {
  InsertPlan refused;
  refused.point = p;
  if (!p.allFinite()) {
    refused.reason = RefuseReason::NotFinite;
    return refused;
  }
  const PlaneTransform tr(m);
  if (tr.orientation() == 0) {
    refused.reason = RefuseReason::BadTransform;
    return refused;
  }
  return makePlan(tri, p, MetricConflict(tr, p), start, extra);
}

InsertPlan planInsertion(Triangulation2d& tri, const Vec2& p, const ConflictTest& test, TriId start,
                         const NewTriangleTest* extra) {
  if (!p.allFinite()) {
    InsertPlan refused;
    refused.point = p;
    refused.reason = RefuseReason::NotFinite;
    return refused;
  }
  return makePlan<ConflictTest>(tri, p, test, start, extra);
}

InsertResult applyInsertion(Triangulation2d& tri, const InsertPlan& plan) {
  InsertResult res;
  res.status = plan.status;
  res.reason = plan.reason;
  res.incircleTests = plan.incircleTests;
  res.pruned = plan.pruned;
  res.walkSteps = plan.location.steps;
  if (plan.status == InsertStatus::Duplicate) res.vertex = plan.duplicate;
  if (plan.status != InsertStatus::Inserted) return res;
  if (plan.revision != tri.revision() || plan.workspace != &tri.workspace())
    throw MeshingError("applyInsertion: the triangulation changed after the plan was made");
  Workspace2d& ws = tri.workspace();
  const VertexId vp = tri.addVertex(plan.point);
  if (ws.startOf.size() < tri.numVertices()) ws.startOf.resize(tri.numVertices() + tri.numVertices() / 2);
  for (TriId t : ws.cavity) tri.freeTriangle(t);
  ws.created.clear();
  // Fan (p, a, b) over every boundary edge a→b; edge 0 of the new triangle is a→b.
  for (const CavityEdge& e : ws.boundary) {
    const TriId nt = tri.createTriangle(vp, e.a, e.b);
    if (e.outside.valid()) tri.link(nt, 0, e.outside, e.outsideEdge);
    if (e.constrained) tri.setConstrainedBit(nt, 0, true);
    ws.startOf[e.a.index] = nt.index;
    ws.created.push_back(nt);
  }
  // Edge 1 of (p, a, b) is (b, p): edge 2 of the fan triangle starting at b.
  for (std::size_t k = 0; k < ws.created.size(); ++k) {
    const TriId nt = ws.created[k];
    tri.link(nt, 1, TriId(ws.startOf[ws.boundary[k].b.index]), 2);
    tri.setVertexTriangle(ws.boundary[k].a, nt);
  }
  tri.setVertexTriangle(vp, ws.created.front());
  res.vertex = vp;
  res.triangle = ws.created.front();
  res.cavitySize = ws.cavity.size();
  res.created = ws.created.size();
  return res;
}

InsertResult insertPoint(Triangulation2d& tri, const Vec2& p, const Mat2& m, TriId start) {
  return applyInsertion(tri, planInsertion(tri, p, m, start));
}

}  // namespace aniso::del2d
