#include "mesher/surface/improve/VertexMetricCache.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "mesher/core/Error.h"

namespace aniso::improve {
namespace {

using del2d::kNext;
using del2d::kPrev;

Mat2 inverse2(const Mat2& s) {
  const double det = s(0, 0) * s(1, 1) - s(0, 1) * s(1, 0);
  Mat2 r;
  r << s(1, 1) / det, -s(0, 1) / det, -s(1, 0) / det, s(0, 0) / det;
  return r;
}

/// δ_M (eq. 2.24–2.25) from the cached tensors and inverses.
double metricJump(const Mat2& s1, const Mat2& inv1, const Mat2& s2, const Mat2& inv2) {
  return (inv1 * s2 + inv2 * s1 - 2 * Mat2::Identity()).norm();
}

/// Angle at p between the directions to a and b, measured with S.
double metricAngle(const Mat2& s, const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 x = s * (a - p), y = s * (b - p);
  return std::atan2(std::abs(x.x() * y.y() - x.y() * y.x()), x.dot(y));
}

}  // namespace

bool symmetricTransform(const Mat2& m, Mat2& s) {
  if (!m.allFinite()) return false;
  const double t00 = m(0, 0) * m(0, 0) + m(1, 0) * m(1, 0);
  const double t11 = m(0, 1) * m(0, 1) + m(1, 1) * m(1, 1);
  const double t01 = m(0, 0) * m(0, 1) + m(1, 0) * m(1, 1);
  const double root = std::abs(m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0));  // √det(MᵀM)
  if (!(root > 0)) return false;
  const double scale = std::sqrt(t00 + t11 + 2 * root);
  s << (t00 + root) / scale, t01 / scale, t01 / scale, (t11 + root) / scale;
  const double det = s(0, 0) * s(1, 1) - s(0, 1) * s(1, 0);
  return s.allFinite() && s(0, 0) > 0 && det > 0 && std::isfinite(1 / det);
}

void VertexMetricCache::update(const Triangulation2d& tri, const ControlSpace2d& cs,
                               std::span<const std::uint8_t> fixed) {
  const std::size_t n = tri.numVertices();
  if (fixed.size() < n)
    throw MeshingError("improve: " + std::to_string(fixed.size()) + " fixed flags for " +
                       std::to_string(n) + " vertices");
  s_.assign(n, Mat2::Identity());
  inv_.assign(n, Mat2::Identity());
  grad_.assign(n, 0.0);
  angle_.assign(n, 0.0);
  ideal_.assign(n, 6);
  flags_.assign(n, 0);
  classifyTopology(tri);
  for (std::size_t v = 0; v < n; ++v) {  // one control-space evaluation per used vertex
    if (!(flags_[v] & kUsed)) continue;
    const Mat2 m = cs.getMetric(tri.point(VertexId(static_cast<std::uint32_t>(v)))).transformation();
    if (symmetricTransform(m, s_[v])) inv_[v] = inverse2(s_[v]);
    else flags_[v] |= kBadMetric, s_[v] = Mat2::Identity();
  }
  substituteUnusable(tri);
  measureNeighbourhoods(tri);
  markDegenerateEdges(tri);
  for (std::size_t v = 0; v < n; ++v) {
    const std::uint8_t f = flags_[v];
    if (f & kOpen) {
      const long sectors = std::lround(angle_[v] / (std::numbers::pi / 3));
      ideal_[v] = static_cast<int>(std::max(1L, sectors)) + 1;
    }
    const std::uint8_t holds = kOpen | kConstrained | kBadMetric | kDegenerate | kNearDegenerate;
    if ((f & kUsed) && fixed[v] == 0 && !(f & holds)) flags_[v] |= kMovable;
  }
}

void VertexMetricCache::classifyTopology(const Triangulation2d& tri) {
  for (std::uint32_t ti = 0; ti < tri.triangleSlots(); ++ti) {
    const TriId t(ti);
    if (!tri.isAlive(t)) continue;
    const std::uint32_t* tv = tri.triVertices(t);
    for (int i = 0; i < 3; ++i) {
      flags_[tv[i]] |= kUsed;
      std::uint8_t edgeFlags = 0;
      if (!tri.neighbour(t, i).valid()) edgeFlags |= kOpen;
      if (tri.isConstrained(t, i)) edgeFlags |= kConstrained;
      flags_[tv[kNext[i]]] |= edgeFlags;
      flags_[tv[kPrev[i]]] |= edgeFlags;
    }
  }
}

void VertexMetricCache::substituteUnusable(const Triangulation2d& tri) {
  // The first usable neighbour's metric, visiting the triangles by index.
  for (std::uint32_t ti = 0; ti < tri.triangleSlots(); ++ti) {
    const TriId t(ti);
    if (!tri.isAlive(t)) continue;
    const std::uint32_t* tv = tri.triVertices(t);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = tv[i], b = tv[kNext[i]];
      for (const auto& [bad, good] : {std::pair{a, b}, std::pair{b, a}}) {
        if (!(flags_[bad] & kBadMetric) || (flags_[bad] & kSubstituted) || (flags_[good] & kBadMetric))
          continue;
        s_[bad] = s_[good], inv_[bad] = inv_[good];
        flags_[bad] |= kSubstituted;
      }
    }
  }
}

void VertexMetricCache::measureNeighbourhoods(const Triangulation2d& tri) {
  // Gradation over the unique edges; metric angles of the border vertices.
  for (std::uint32_t ti = 0; ti < tri.triangleSlots(); ++ti) {
    const TriId t(ti);
    if (!tri.isAlive(t)) continue;
    const std::uint32_t* tv = tri.triVertices(t);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = tv[i];
      if (flags_[v] & kOpen)
        angle_[v] += metricAngle(s_[v], tri.point(VertexId(v)), tri.point(VertexId(tv[kNext[i]])),
                                 tri.point(VertexId(tv[kPrev[i]])));
      const TriId u = tri.neighbour(t, i);
      if (u.valid() && u.index < ti) continue;
      const std::uint32_t a = tv[kNext[i]], b = tv[kPrev[i]];
      const double jump = metricJump(s_[a], inv_[a], s_[b], inv_[b]);
      grad_[a] = std::max(grad_[a], jump);
      grad_[b] = std::max(grad_[b], jump);
    }
  }
}

void VertexMetricCache::markDegenerateEdges(const Triangulation2d& tri) {
  const std::size_t slots = tri.triangleSlots();
  for (std::uint32_t ti = 0; ti < slots; ++ti) {
    const TriId t(ti);
    if (!tri.isAlive(t)) continue;
    const std::uint32_t* tv = tri.triVertices(t);
    for (int i = 0; i < 3; ++i) {
      if (!tri.isConstrained(t, i)) continue;
      const std::uint32_t a = tv[kNext[i]], b = tv[kPrev[i]];
      const Vec2 e = tri.point(VertexId(b)) - tri.point(VertexId(a));
      const bool unusable = (flags_[a] & kBadMetric) || (flags_[b] & kBadMetric);
      if (unusable || std::max((s_[a] * e).norm(), (s_[b] * e).norm()) < kDegenerateEdgeLength)
        flags_[a] |= kDegenerate, flags_[b] |= kDegenerate;
    }
  }
  for (std::uint32_t ti = 0; ti < slots; ++ti) {
    const TriId t(ti);
    if (!tri.isAlive(t)) continue;
    const std::uint32_t* tv = tri.triVertices(t);
    if ((flags_[tv[0]] | flags_[tv[1]] | flags_[tv[2]]) & kDegenerate)
      for (int k = 0; k < 3; ++k) flags_[tv[k]] |= kNearDegenerate;
  }
}

bool VertexMetricCache::frozen(const Triangulation2d& tri, TriId t) const {
  const std::uint32_t* tv = tri.triVertices(t);
  return ((flags_[tv[0]] | flags_[tv[1]] | flags_[tv[2]]) & kDegenerate) != 0;
}

Mat2 VertexMetricCache::blend(const VertexId* v, int n) const {
  std::uint32_t ids[4];
  const int m = std::clamp(n, 1, 4);
  for (int k = 0; k < m; ++k) {  // insertion sort: increasing vertex index
    int j = k;
    for (; j > 0 && ids[j - 1] > v[k].index; --j) ids[j] = ids[j - 1];
    ids[j] = v[k].index;
  }
  bool same = true;
  for (int k = 1; k < m && same; ++k) same = s_[ids[k]] == s_[ids[0]];
  if (same) return s_[ids[0]];
  Mat2 sum = inv_[ids[0]];
  for (int k = 1; k < m; ++k) sum += inv_[ids[k]];
  return inverse2(sum / m);
}

namespace {
template <class OnTriangle>
bool walkRing(const Triangulation2d& tri, VertexId v, std::vector<VertexId>& ring, std::size_t maxDegree,
              OnTriangle onTriangle) {
  ring.clear();
  const TriId t0 = tri.vertexTriangle(v);
  if (!t0.valid()) return false;
  TriId t = t0;
  do {
    const int k = tri.localIndex(t, v);
    if (k < 0) return false;
    ring.push_back(tri.vertex(t, kNext[k]));
    onTriangle(t);
    t = tri.neighbour(t, kNext[k]);
    if (!t.valid() || ring.size() > maxDegree) return false;
  } while (t != t0);
  return true;
}
}  // namespace

bool gatherRing(const Triangulation2d& tri, VertexId v, std::vector<VertexId>& ring, std::size_t maxDegree) {
  return walkRing(tri, v, ring, maxDegree, [](TriId) {});
}

bool gatherRing(const Triangulation2d& tri, VertexId v, std::vector<VertexId>& ring, std::vector<TriId>& tris,
                std::size_t maxDegree) {
  tris.clear();
  return walkRing(tri, v, ring, maxDegree, [&](TriId t) { tris.push_back(t); });
}

void moveVertex(Triangulation2d& tri, VertexId v, const Vec2& p) {
  const_cast<Vec2&>(tri.point(v)) = p;
}

bool VertexMetricCache::fanUpright(const Triangulation2d& tri, const Vec2& x, std::span<const VertexId> ring) const {
  if (!lift_ || !lift_->active()) return true;
  const face::LiftedPoint lx = lift_->lift(x);
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k)
    if (!face::SurfaceLift::upright(lx, lift_->at(tri, ring[k]), lift_->at(tri, ring[k + 1 == n ? 0 : k + 1])))
      return false;
  return true;
}

}  // namespace aniso::improve
