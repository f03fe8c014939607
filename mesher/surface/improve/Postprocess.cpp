#include "mesher/surface/improve/Postprocess.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/delaunay/EdgeFlip.h"
#include "mesher/metric/MeanRatio.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::improve {
namespace {

using del2d::kNext;
using del2d::kPrev;

/// Flips edge i of t when that raises the worse η_M of the pair.
bool qualityFlip(Triangulation2d& tri, const VertexMetricCache& metrics, TriId t, int i) {
  if (metrics.edgeFrozen(tri, t, i)) return false;
  const del2d::FlipPlan plan = del2d::canFlip(tri, t, i);
  if (!plan.legal || !metrics.flipUpright(tri, plan)) return false;
  const VertexId q[4] = {plan.a, plan.b, plan.c, plan.d};
  const Mat2 m = metrics.blend(q, 4);
  const Vec2 a = tri.point(plan.a), b = tri.point(plan.b), c = tri.point(plan.c), d = tri.point(plan.d);
  const double before = std::min(meanRatio(m, a, b, c), meanRatio(m, d, c, b));
  const double after = std::min(meanRatio(m, a, b, d), meanRatio(m, a, d, c));
  if (!(after > before)) return false;
  del2d::flip(tri, plan);
  return true;
}

/// Relocate-and-flip: flips edge i of t (quadrilateral a-b-d-c, edge (b, c), del2d
/// FlipPlan naming) together with moving one movable vertex v of the quadrilateral to the
/// average of its neighbours after the flip (the plain average is the metric-space average
/// for v's metric). This removes an edge that cannot be flipped alone because the
/// quadrilateral is not convex at v, or adds an edge at a vertex of degree 3 so that it can
/// leave a corner. The whole result is checked first: every new triangle counter-clockwise
/// (exact orient2d) and its worst η_M above the worst of the triangles it replaces (all in
/// v's metric); then v moves and the edge flips (legal by the checks).
bool relocateAndFlip(Triangulation2d& tri, const VertexMetricCache& metrics, TriId t, int i, int which,
                     std::vector<VertexId>& ring, std::vector<Vec2>& p) {
  const TriId u = tri.neighbour(t, i);
  if (!u.valid() || tri.isConstrained(t, i) || metrics.edgeFrozen(tri, t, i)) return false;
  const int j = tri.neighbourIndex(u, t);
  if (j < 0) return false;
  const VertexId a = tri.vertex(t, i), b = tri.vertex(t, kNext[i]), c = tri.vertex(t, kPrev[i]), d = tri.vertex(u, j);
  const VertexId quad[4] = {a, b, c, d};
  const VertexId v = quad[which];
  if (!metrics.movable(v) || !gatherRing(tri, v, ring)) return false;
  const Mat2& s = metrics.transform(v);
  const std::size_t n = ring.size();
  const Vec2 q = tri.point(v);
  // Replaced triangles: v's star, and t or u when v is not in it.
  double before = 2.0;
  for (std::size_t k = 0; k < n; ++k)
    before = std::min(before, meanRatio(s, q, tri.point(ring[k]), tri.point(ring[k + 1 == n ? 0 : k + 1])));
  if (v == a) before = std::min(before, meanRatio(s, tri.point(d), tri.point(c), tri.point(b)));
  if (v == d) before = std::min(before, meanRatio(s, tri.point(a), tri.point(b), tri.point(c)));
  // v's ring after the flip: a gains d between b and c, d gains a between c and b, b loses
  // c, c loses b.
  p.clear();
  std::vector<VertexId> ids;
  for (std::size_t k = 0; k < n; ++k) {
    const VertexId x = ring[k], next = ring[k + 1 == n ? 0 : k + 1];
    if ((v == b && x == c) || (v == c && x == b)) continue;
    ids.push_back(x);
    if (v == a && x == b && next == c) ids.push_back(d);
    if (v == d && x == c && next == b) ids.push_back(a);
  }
  for (const VertexId y : ids) p.push_back(tri.point(y));
  const std::size_t m = p.size();
  if (m < 3 || m == n) return false;  // m == n: the ring did not have the expected edge
  Vec2 sum = Vec2::Zero();
  for (const Vec2& y : p) sum += y;
  const Vec2 x = sum / static_cast<double>(m);
  double after = 2.0, turn = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    const Vec2 &y = p[k], &z = p[k + 1 == m ? 0 : k + 1];
    if (!(predicates::orient2d(x.data(), y.data(), z.data()) > 0)) return false;
    after = std::min(after, meanRatio(s, x, y, z));
    const Vec2 e = y - x, f = z - x;
    turn += std::atan2(e.x() * f.y() - e.y() * f.x(), e.dot(f));
  }
  // The new ring is not the link of an old vertex and need not be a simple polygon: with
  // every fan triangle counter-clockwise it is one exactly when it winds once around x.
  if (turn > 3 * std::numbers::pi) return false;
  // The new triangle without v, when v is an endpoint of the old edge.
  if (v == b || v == c) {
    const Vec2 &e0 = tri.point(a), &e1 = v == b ? tri.point(d) : tri.point(b), &e2 = v == b ? tri.point(c) : tri.point(d);
    if (!(predicates::orient2d(e0.data(), e1.data(), e2.data()) > 0)) return false;
    after = std::min(after, meanRatio(s, e0, e1, e2));
    if (!metrics.triangleUpright(tri, a, v == b ? d : b, v == b ? c : d)) return false;
  }
  if (!(after > before) || !metrics.fanUpright(tri, x, ids)) return false;
  moveVertex(tri, v, x);
  const del2d::FlipPlan plan = del2d::canFlip(tri, t, i);
  if (!plan.legal) {  // cannot happen: both new triangles were checked above
    moveVertex(tri, v, q);
    return false;
  }
  del2d::flip(tri, plan);
  return true;
}

/// Hill climbing of one movable vertex towards the ideal point of its worst star triangle.
int optimiseVertex(Triangulation2d& tri, const VertexMetricCache& metrics, VertexId v, int iterations,
                   std::vector<VertexId>& ring, std::vector<Vec2>& p) {
  if (!metrics.movable(v) || !gatherRing(tri, v, ring)) return 0;
  const Mat2& s = metrics.transform(v);
  const Mat2& inv = metrics.inverse(v);
  const std::size_t n = ring.size();
  p.clear();
  for (VertexId w : ring) p.push_back(s * tri.point(w));  // metric space of v
  const auto worst = [&](const Vec2& mq, std::size_t* at) {
    double w = 2.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double e = meanRatio(mq, p[k], p[k + 1 == n ? 0 : k + 1]);
      if (e < w) w = e, *at = k;
    }
    return w;
  };
  const auto valid = [&](const Vec2& x) {
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 &b = tri.point(ring[k]), &c = tri.point(ring[k + 1 == n ? 0 : k + 1]);
      if (!(predicates::orient2d(x.data(), b.data(), c.data()) > 0)) return false;
    }
    return metrics.fanUpright(tri, x, ring);
  };
  int moves = 0;
  for (int it = 0; it < iterations; ++it) {
    const Vec2 q = tri.point(v);
    std::size_t k = 0;
    const double before = worst(s * q, &k);
    // Apex of the equilateral triangle on the edge (b, c), left of b → c, in metric space.
    const Vec2 &b = p[k], &c = p[k + 1 == n ? 0 : k + 1];
    const Vec2 e = c - b;
    const Vec2 apex = 0.5 * (b + c) + (std::sqrt(3.0) / 2) * Vec2(-e.y(), e.x());
    const Vec2 target = inv * apex;
    bool improved = false;
    for (const double step : {1.0, 0.5, 0.25}) {
      const Vec2 x = q + step * (target - q);
      if (!x.allFinite() || x == q) break;
      std::size_t unused = 0;
      if (!(worst(s * x, &unused) > before) || !valid(x)) continue;
      moveVertex(tri, v, x);
      improved = true;
      break;
    }
    if (!improved) break;
    ++moves;
  }
  return moves;
}

}  // namespace

double triangleQuality(const Triangulation2d& tri, const VertexMetricCache& metrics, TriId t) {
  const VertexId v[3] = {tri.vertex(t, 0), tri.vertex(t, 1), tri.vertex(t, 2)};
  return meanRatio(metrics.blend(v, 3), tri.point(v[0]), tri.point(v[1]), tri.point(v[2]));
}

long long countBadTriangles(const Triangulation2d& tri, const VertexMetricCache& metrics, double threshold) {
  long long bad = 0;
  for (std::uint32_t ti = 0; ti < tri.triangleSlots(); ++ti)
    if (tri.isAlive(TriId(ti)) && triangleQuality(tri, metrics, TriId(ti)) < threshold) ++bad;
  return bad;
}

PostprocessStats postprocess(Triangulation2d& tri, const VertexMetricCache& metrics,
                             const PostprocessOptions& options) {
  if (metrics.size() != tri.numVertices())
    throw MeshingError("postprocess: the metric cache does not match the triangulation");
  if (!std::isfinite(options.badQuality) || options.rounds < 0 || options.vertexIterations < 0)
    throw MeshingError("postprocess: invalid options");
  PostprocessStats st;
  st.badBefore = countBadTriangles(tri, metrics, options.badQuality);
  std::vector<VertexId> ring, star;
  std::vector<Vec2> p;
  ring.reserve(32), star.reserve(32), p.reserve(32);
  for (int round = 0; round < options.rounds && st.badBefore > 0; ++round) {
    long long changes = 0;
    for (std::uint32_t ti = 0; ti < tri.triangleSlots(); ++ti) {
      const TriId t(ti);
      if (!tri.isAlive(t) || metrics.frozen(tri, t) || !(triangleQuality(tri, metrics, t) < options.badQuality))
        continue;
      bool flipped = false;
      for (int i = 0; i < 3 && !flipped; ++i) flipped = qualityFlip(tri, metrics, t, i);
      for (int i = 0; i < 3 && !flipped; ++i)
        for (int which = 0; which < 4 && !flipped; ++which)
          flipped = relocateAndFlip(tri, metrics, t, i, which, ring, p);
      // A vertex of the triangle stuck in a corner of its star: flip an edge opposite it.
      for (int k = 0; k < 3 && !flipped; ++k) {
        const VertexId v = tri.vertex(t, k);
        if (!metrics.movable(v) || !gatherRing(tri, v, star)) continue;
        for (std::size_t r = 0; r < star.size() && !flipped; ++r) {
          TriId s;
          int i = -1;
          if (tri.findEdge(star[r], star[r + 1 == star.size() ? 0 : r + 1], s, i))
            flipped = relocateAndFlip(tri, metrics, s, i, 0, ring, p);
        }
      }
      if (flipped) {
        ++st.flips, ++changes;
        if (!(triangleQuality(tri, metrics, t) < options.badQuality)) continue;
      }
      for (int k = 0; k < 3; ++k) {
        const int moved = optimiseVertex(tri, metrics, tri.vertex(t, k), options.vertexIterations, ring, p);
        st.moves += moved, changes += moved;
      }
    }
    if (changes == 0) break;
  }
  st.badAfter = countBadTriangles(tri, metrics, options.badQuality);
  return st;
}

}  // namespace aniso::improve
