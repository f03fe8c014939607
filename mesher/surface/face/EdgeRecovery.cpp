#include "mesher/surface/face/EdgeRecovery.h"

#include <deque>

#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/delaunay/PlaneTransform.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/surface/face/FaceMetric.h"

namespace aniso::face {

using namespace del2d;

namespace {

using Edge = std::pair<VertexId, VertexId>;

double orient(const Triangulation2d& tri, VertexId a, VertexId b, VertexId c) {
  return predicates::orient2d(tri.coords(a), tri.coords(b), tri.coords(c));
}

/// Whether x lies on the ray a→b (collinear, same direction); only called when collinear.
bool onRay(const Triangulation2d& tri, VertexId a, VertexId b, VertexId x) {
  return (tri.point(x) - tri.point(a)).dot(tri.point(b) - tri.point(a)) > 0;
}

/// The first crossing: the triangle around a whose angle at a contains the direction a→b,
/// as (triangle, local index of a). Sets res.status on a blocker.
bool firstCrossing(const Triangulation2d& tri, VertexId a, VertexId b, TriId& t, int& ia, EdgeRecovery& res) {
  const TriId start = tri.vertexTriangle(a);
  TriId cur = start;
  for (std::size_t guard = 0; guard <= tri.triangleSlots() && cur.valid(); ++guard) {
    const int i = tri.localIndex(cur, a);
    if (i < 0) break;
    const VertexId v1 = tri.vertex(cur, kNext[i]), v2 = tri.vertex(cur, kPrev[i]);
    const double s1 = orient(tri, a, b, v1), s2 = orient(tri, a, b, v2);
    if (s1 == 0 && onRay(tri, a, b, v1)) {
      res.status = RecoveryStatus::VertexOnSegment;
      res.blocker = v1;
      return false;
    }
    if (s1 < 0 && s2 > 0) {
      t = cur;
      ia = i;
      return true;
    }
    cur = tri.neighbour(cur, kNext[i]);  // counter-clockwise around a
    if (cur == start) break;
  }
  res.status = RecoveryStatus::Failed;
  return false;
}

/// Step 1: the edges crossed by a→b, in order; false (status set) on a blocker.
bool collectCrossings(const Triangulation2d& tri, VertexId a, VertexId b, std::vector<Edge>& out,
                      EdgeRecovery& res) {
  TriId t;
  int ia = 0;
  if (!firstCrossing(tri, a, b, t, ia, res)) return false;
  int e = ia;
  VertexId r = tri.vertex(t, kNext[ia]), l = tri.vertex(t, kPrev[ia]);
  for (std::size_t guard = 0; guard <= tri.triangleSlots(); ++guard) {
    if (tri.isConstrained(t, e)) {
      res.status = RecoveryStatus::CrossesConstrained;
      res.crossA = r;
      res.crossB = l;
      return false;
    }
    const TriId u = tri.neighbour(t, e);
    if (!u.valid()) break;
    out.emplace_back(r, l);
    const int j = tri.neighbourIndex(u, t);
    const VertexId d = tri.vertex(u, j);
    if (d == b) return true;
    const double sd = orient(tri, a, b, d);
    if (sd == 0) {
      res.status = RecoveryStatus::VertexOnSegment;
      res.blocker = d;
      return false;
    }
    if (sd < 0) {
      e = kPrev[j];  // edge (d, l)
      r = d;
    } else {
      e = kNext[j];  // edge (r, d)
      l = d;
    }
    t = u;
  }
  res.status = RecoveryStatus::Failed;
  return false;
}

bool crossesProperly(const Triangulation2d& tri, VertexId a, VertexId b, VertexId x, VertexId y) {
  const double sx = orient(tri, a, b, x), sy = orient(tri, a, b, y);
  if (!((sx < 0 && sy > 0) || (sx > 0 && sy < 0))) return false;
  const double sa = orient(tri, x, y, a), sb = orient(tri, x, y, b);
  return (sa < 0 && sb > 0) || (sa > 0 && sb < 0);
}

bool locateEdge(const Triangulation2d& tri, const Edge& e, TriId& t, int& i) {
  return tri.findEdge(e.first, e.second, t, i) || tri.findEdge(e.second, e.first, t, i);
}

}  // namespace

EdgeRecovery recoverEdge(Triangulation2d& tri, VertexId a, VertexId b) {
  EdgeRecovery res;
  TriId t;
  int i = 0;
  if (locateEdge(tri, {a, b}, t, i)) {
    res.status = RecoveryStatus::Present;
    return res;
  }
  std::vector<Edge> crossing;
  if (!collectCrossings(tri, a, b, crossing, res)) return res;
  res.crossings = crossing.size();
  std::deque<Edge> queue(crossing.begin(), crossing.end());
  const std::size_t n = crossing.size();
  const std::size_t maxIterations = 1000 + 16 * n * n;
  for (std::size_t it = 0; !queue.empty(); ++it) {
    if (it == maxIterations) {
      res.status = RecoveryStatus::Failed;
      return res;
    }
    const Edge e = queue.front();
    queue.pop_front();
    if (!locateEdge(tri, e, t, i)) {
      res.status = RecoveryStatus::Failed;
      return res;
    }
    const FlipPlan plan = canFlip(tri, t, i);
    if (!plan.legal) {
      queue.push_back(e);
      continue;
    }
    flip(tri, plan);
    ++res.flips;
    const Edge diagonal(plan.a, plan.d);
    const bool isTarget = (plan.a == a && plan.d == b) || (plan.a == b && plan.d == a);
    if (isTarget) continue;
    if (crossesProperly(tri, a, b, plan.a, plan.d)) queue.push_back(diagonal);
    else res.newEdges.push_back(diagonal);
  }
  res.status = locateEdge(tri, {a, b}, t, i) ? RecoveryStatus::Recovered : RecoveryStatus::Failed;
  return res;
}

std::vector<std::string> recoverBoundaryEdges(Triangulation2d& tri, const FlatBoundary& boundary,
                                              const std::vector<VertexId>& vertexOf, const ControlSpace2d& cs,
                                              BoundaryRecoveryStats* stats) {
  BoundaryRecoveryStats local;
  BoundaryRecoveryStats& st = stats != nullptr ? *stats : local;
  std::vector<std::string> problems;
  const auto n = static_cast<std::uint32_t>(boundary.size());
  std::vector<std::uint32_t> nodeOf(tri.numVertices(), kNone);
  for (std::uint32_t k = 0; k < n; ++k) nodeOf[vertexOf[k].index] = k;
  auto name = [&](VertexId v) {
    const std::uint32_t k = v.index < nodeOf.size() ? nodeOf[v.index] : kNone;
    return k != kNone ? boundary.describe(k) : std::string("box corner ") + std::to_string(v.index);
  };
  auto edgeName = [&](std::uint32_t k) {
    return "boundary edge (" + boundary.describe(k) + ", " + boundary.describe(boundary.next[k]) + ")";
  };
  std::vector<std::uint32_t> missing;
  for (std::uint32_t k = 0; k < n; ++k)
    if (!tri.setConstrainedEdge(vertexOf[k], vertexOf[boundary.next[k]])) missing.push_back(k);
  st.missing = missing.size();
  std::vector<TriId> touched;
  for (std::uint32_t k : missing) {
    const VertexId a = vertexOf[k], b = vertexOf[boundary.next[k]];
    const EdgeRecovery r = recoverEdge(tri, a, b);
    st.flips += r.flips;
    switch (r.status) {
      case RecoveryStatus::Present:
      case RecoveryStatus::Recovered: break;
      case RecoveryStatus::VertexOnSegment:
        problems.push_back(edgeName(k) + " passes through " + name(r.blocker));
        continue;
      case RecoveryStatus::CrossesConstrained:
        problems.push_back(edgeName(k) + " crosses boundary edge (" + name(r.crossA) + ", " + name(r.crossB) + ")");
        continue;
      case RecoveryStatus::Failed:
        problems.push_back(edgeName(k) + " could not be recovered by edge flips");
        continue;
    }
    tri.setConstrainedEdge(a, b);
    ++st.recovered;
    touched.clear();
    for (const auto& e : r.newEdges) {
      TriId t;
      int i = 0;
      if (locateEdge(tri, e, t, i)) {
        touched.push_back(t);
        const TriId u = tri.neighbour(t, i);
        if (u.valid()) touched.push_back(u);
      }
    }
    if (touched.empty()) continue;
    const PlaneTransform m(metricAt(cs, 0.5 * (tri.point(a) + tri.point(b))));
    if (m.orientation() != 0) restoreDelaunay(tri, touched, m, FlipCriterion::EmptyCircle, 16 * touched.size() + 64);
  }
  return problems;
}

}  // namespace aniso::face
