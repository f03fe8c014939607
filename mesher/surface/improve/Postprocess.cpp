#include "mesher/surface/improve/Postprocess.h"

#include <algorithm>
#include <cmath>
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
  const del2d::FlipPlan plan = del2d::canFlip(tri, t, i);
  if (!plan.legal) return false;
  const VertexId q[4] = {plan.a, plan.b, plan.c, plan.d};
  const Mat2 m = metrics.blend(q, 4);
  const Vec2 a = tri.point(plan.a), b = tri.point(plan.b), c = tri.point(plan.c), d = tri.point(plan.d);
  const double before = std::min(meanRatio(m, a, b, c), meanRatio(m, d, c, b));
  const double after = std::min(meanRatio(m, a, b, d), meanRatio(m, a, d, c));
  if (!(after > before)) return false;
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
    return true;
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
  std::vector<VertexId> ring;
  std::vector<Vec2> p;
  ring.reserve(32), p.reserve(32);
  for (int round = 0; round < options.rounds && st.badBefore > 0; ++round) {
    long long changes = 0;
    for (std::uint32_t ti = 0; ti < tri.triangleSlots(); ++ti) {
      const TriId t(ti);
      if (!tri.isAlive(t) || !(triangleQuality(tri, metrics, t) < options.badQuality)) continue;
      bool flipped = false;
      for (int i = 0; i < 3 && !flipped; ++i) flipped = qualityFlip(tri, metrics, t, i);
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
