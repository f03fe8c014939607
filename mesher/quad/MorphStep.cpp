#include "mesher/quad/MorphStep.h"

#include <algorithm>
#include <array>
#include <deque>

#include "mesher/quad/TopEdgeRecovery.h"

namespace aniso::quad {
namespace {

bool isQuadEdge(const Corners& q, int x, int y) {
  for (int i = 0; i < 4; ++i)
    if ((q[i] == x && q[(i + 1) % 4] == y) || (q[i] == y && q[(i + 1) % 4] == x)) return true;
  return false;
}

/// The live triangles enclosed by the quad's outline, flooded from `seed`; empty when the
/// flood meets anything but triangles inside or exceeds `limit`.
std::vector<int> enclosed(const QuadMesh2d& mesh, const Corners& quad, int seed, int limit) {
  std::vector<int> out{seed};
  std::deque<int> queue{seed};
  while (!queue.empty()) {
    const int f = queue.front();
    queue.pop_front();
    for (int k = 0; k < 3; ++k) {
      const int x = mesh.corners[f][k], y = mesh.corners[f][(k + 1) % 3];
      if (isQuadEdge(quad, x, y)) continue;
      const int g = mesh.adj[f][k];
      if (g == kNone || !mesh.isTriangle(g)) return {};
      if (std::find(out.begin(), out.end(), g) != out.end()) continue;
      if (static_cast<int>(out.size()) >= limit) return {};
      out.push_back(g);
      queue.push_back(g);
    }
  }
  // Every quad edge must be an edge of the set (the outline is exactly the quad).
  int outline = 0;
  for (int f : out)
    for (int k = 0; k < 3; ++k) outline += isQuadEdge(quad, mesh.corners[f][k], mesh.corners[f][(k + 1) % 3]);
  return outline == 4 ? out : std::vector<int>{};
}

/// Laplace smoothing of the region vertices around `vertices` (not on the front).
void smoothAhead(QuadMesh2d& mesh, VertexMetrics& metrics, const std::vector<std::uint8_t>& onFront, int q,
                 int sweeps) {
  std::vector<int> around, ring;
  bool closed = false;
  for (int i = 0; i < 4; ++i) {
    around.clear();
    mesh.star(mesh.corners[q][i], q, around, closed);
    for (int f : around)
      if (mesh.isTriangle(f))
        for (int k = 0; k < 3; ++k) ring.push_back(mesh.corners[f][k]);
  }
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (int v : ring) {
      if (mesh.boundary[v] || (v < static_cast<int>(onFront.size()) && onFront[v])) continue;
      int at = q;
      // An element at v: a triangle of a quad corner's star that has v.
      around.clear();
      for (int i = 0; i < 4 && at == q; ++i) {
        std::vector<int> s;
        mesh.star(mesh.corners[q][i], q, s, closed);
        for (int f : s)
          if (mesh.isTriangle(f) && mesh.cornerIndex(f, v) != kNone) at = f;
      }
      if (at == q) continue;
      mesh.star(v, at, around, closed);
      if (!closed) continue;
      double worst = 2;
      Vec2 sum(0, 0);
      for (int f : around) {
        if (!mesh.isTriangle(f)) {
          worst = -3;
          break;
        }
        worst = std::min(worst, elementQuality(mesh, metrics, mesh.corners[f]));
        sum += mesh.uv[mesh.corners[f][(mesh.cornerIndex(f, v) + 1) % 3]];
      }
      if (worst < -2) continue;
      const Vec2 old = mesh.uv[v];
      mesh.uv[v] = sum / static_cast<double>(around.size());
      metrics.refreshPoint(v);
      double after = 2;
      for (int f : around) after = std::min(after, elementQuality(mesh, metrics, mesh.corners[f]));
      if (!(after > 0 && after >= worst)) {
        mesh.uv[v] = old;
        metrics.refreshPoint(v);
      } else {
        metrics.invalidate(v);
      }
    }
}

/// The base triangle (edge a→b) after swaps: e if still alive, else among the newest
/// elements (every swap appends its two triangles; a side edge and the upper edge make at
/// most 1 + 1 + maxSwaps of them).
int findBase(const QuadMesh2d& mesh, int a, int b, int e) {
  if (mesh.isTriangle(e) && mesh.edgeIndex(e, a, b) != kNone) return e;
  for (int f = mesh.numElements() - 1; f >= 0 && f >= mesh.numElements() - 64; --f)
    if (mesh.isTriangle(f) && mesh.edgeIndex(f, a, b) != kNone) return f;
  return kNone;
}

}  // namespace

MorphResult morphFrontEdge(QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k,
                           const std::vector<std::uint8_t>& onFront, RegionParity& parity, const MorphOptions& o) {
  MorphResult r;
  const int a = mesh.corners[e][k], b = mesh.corners[e][(k + 1) % 3];
  for (bool left : {true, false}) {
    r.transition = transitionSeam(mesh, metrics, e, k, left, o.seam, o.transitionSeam);
    if (r.transition.done) return r;
    const SeamResult s = closeSeam(mesh, metrics, e, k, left, o.seam);
    if (s.done) {
      r.seamVertex = s.vertex;
      r.seamElement = s.element;
      return r;
    }
  }
  for (bool left : {true, false}) {
    r.transition = transitionSplit(mesh, metrics, e, k, left, o.seam.seamAngle, o.transitionSplit);
    if (r.transition.done) {
      r.split = true;
      return r;
    }
  }
  const SideEdge sl = selectSideEdge(mesh, metrics, e, k, true, o.side);
  r.failure = MorphFailure::Side;
  if (sl.vertices.empty()) return r;
  e = findBase(mesh, a, b, e);
  if (e == kNone) return r;
  const SideEdge sr = selectSideEdge(mesh, metrics, e, mesh.edgeIndex(e, a, b), false, o.side);
  if (sr.vertices.empty()) return r;
  e = findBase(mesh, a, b, e);
  if (e == kNone) return r;
  // The pair of sides giving the best quad.
  int c = kNone, d = kNone;
  double best = o.minQuality;
  r.failure = MorphFailure::Degenerate;
  for (int x : sl.vertices)
    for (int y : sr.vertices) {
      if (x == y || x == b || y == a) continue;
      r.failure = std::max(r.failure, MorphFailure::Shape);
      const double q = elementQuality(mesh, metrics, Corners{a, b, y, x});
      if (q >= best) {
        best = q;
        c = x;
        d = y;
      }
    }
  if (c == kNone) return r;
  const Corners quad{a, b, d, c};
  r.failure = MorphFailure::TopEdge;
  // An element at c: the base triangle's fan at a ends at c.
  const RegionFan fan = regionFan(mesh, metrics, a, e, true);
  int hint = kNone;
  for (int f : fan.triangles)
    if (mesh.cornerIndex(f, c) != kNone) hint = f;
  if (hint == kNone || !recoverTopEdge(mesh, c, d, hint)) return r;
  e = findBase(mesh, a, b, e);
  if (e == kNone) return r;
  const std::vector<int> inside = enclosed(mesh, quad, e, o.maxEnclosed);
  r.failure = MorphFailure::Enclosed;
  if (inside.empty() || inside.size() % 2 == 1) return r;
  r.failure = MorphFailure::Parity;
  // c or d may be the vertex a side-edge split of this step made: beyond onFront, not on it
  const auto isOnFront = [&](int v) { return v < static_cast<int>(onFront.size()) && onFront[v]; };
  if ((isOnFront(c) || isOnFront(d)) && !parity.removalKeepsParity(mesh, inside)) return r;
  r.failure = MorphFailure::Shape;
  if (elementQuality(mesh, metrics, quad) < o.minQuality) return r;
  const std::array<Corners, 1> added{quad};
  r.failure = MorphFailure::None;
  r.quad = mesh.replacePatch(inside, added)[0];
  smoothAhead(mesh, metrics, onFront, r.quad, o.smoothSweeps);
  return r;
}

}  // namespace aniso::quad
