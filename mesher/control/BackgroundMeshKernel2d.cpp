// BackgroundMeshKernel<2>: location walk, insertion, stars and triangle geometry of the
// background mesh of surface meshing.
#include "mesher/control/BackgroundMeshKernel2d.h"

#include <algorithm>

#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/PointLocation.h"
#include "mesher/delaunay/Validate2d.h"
#include "mesher/predicates/Predicates.h"

namespace aniso {

using del2d::kNext;
using del2d::kPrev;
using del2d::TriId;
using del2d::VertexId;

namespace {

/// Seeding quadtree leaves of at most this many vertices, all compared per query (the
/// thesis' 300 suits a mesh queried about once per insertion; a control space is queried
/// far more often than it changes, and the nearest vertex leaves a walk of 1–2 steps).
constexpr std::uint32_t kSeedLeaf = 8;

inline std::uint32_t nextRandom(std::uint32_t& s) {
  if (s == 0) s = 0x9E3779B9u;
  s ^= s << 13;
  s ^= s >> 17;
  s ^= s << 5;
  return s;
}

del2d::Triangulation2dOptions kernelOptions(const BackgroundMeshOptions& o) {
  del2d::Triangulation2dOptions t;
  t.boxMargin = o.boxMargin;
  t.quadtree.leafThreshold = kSeedLeaf;
  t.quadtree.sampleSize = kSeedLeaf;
  return t;
}

}  // namespace

BackgroundMeshKernel<2>::BackgroundMeshKernel(const Box2& bounds, const BackgroundMeshOptions& options)
    : tri_(bounds, kernelOptions(options)) {
  tri_.seeds();
}

TriId BackgroundMeshKernel<2>::walk(const Vec2& p, TriId t, std::uint32_t& rng, unsigned& zeros) const {
  // Remembering stochastic visibility walk (as PointLocation.cpp) on the caller's random
  // state; exact orient2d. The edge just crossed has p strictly inside, so its skipped
  // test never hides a zero.
  const double* pp = p.data();
  const std::size_t limit = std::max<std::size_t>(1000, 2 * tri_.numTriangles());
  TriId from;
  for (std::size_t steps = 0; steps < limit; ++steps) {
    const std::uint32_t* tv = tri_.triVertices(t);
    const std::uint32_t* tn = tri_.triNeighbours(t);
    const int r = static_cast<int>(nextRandom(rng) % 3u);
    TriId next;
    bool outside = false;
    zeros = 0;
    for (int k = 0; k < 3; ++k) {
      const int i = r + k < 3 ? r + k : r + k - 3;
      const TriId u(tn[i]);
      if (from.valid() && u == from) continue;
      const double o =
          predicates::orient2d(tri_.coords(VertexId(tv[kNext[i]])), tri_.coords(VertexId(tv[kPrev[i]])), pp);
      if (o == 0) zeros |= 1u << i;
      if (o < 0) {
        if (!u.valid()) {
          outside = true;
          continue;
        }
        next = u;
        break;
      }
    }
    if (next.valid()) {
      from = t;
      t = next;
      continue;
    }
    return outside ? TriId() : t;
  }
  for (std::uint32_t k = 0; k < tri_.triangleSlots(); ++k) {
    const TriId s(k);
    if (!tri_.isAlive(s)) continue;
    const std::uint32_t* tv = tri_.triVertices(s);
    bool inside = true;
    zeros = 0;
    for (int i = 0; i < 3 && inside; ++i) {
      const double o =
          predicates::orient2d(tri_.coords(VertexId(tv[kNext[i]])), tri_.coords(VertexId(tv[kPrev[i]])), pp);
      inside = o >= 0;
      if (o == 0) zeros |= 1u << i;
    }
    if (inside) return s;
  }
  return TriId();
}

TriId BackgroundMeshKernel<2>::locate(const Vec2& p, TriId start, std::uint32_t& rng) const {
  if (!start.valid() || !tri_.isAlive(start)) start = del2d::seedTriangle(tri_, p);
  unsigned zeros = 0;
  TriId t = start.valid() ? walk(p, start, rng, zeros) : TriId();
  if (!t.valid()) return t;
  // On an edge both triangles contain p: take the one with the smaller slot, so that the
  // field (A_t, A_s) does not depend on where the walk came from. On a vertex every set
  // holds the vertex and the ε_M shortcut answers.
  if (zeros == 1u || zeros == 2u || zeros == 4u) {
    const TriId u = tri_.neighbour(t, zeros == 1u ? 0 : zeros == 2u ? 1 : 2);
    if (u.valid() && u.index < t.index) t = u;
  }
  return t;
}

KernelInsertion BackgroundMeshKernel<2>::insert(const Vec2& p, TriId near) {
  const TriId start = near.valid() && tri_.isAlive(near) ? near : TriId();
  const del2d::InsertResult r = del2d::insertPoint(tri_, p, Mat2::Identity(), start);
  KernelInsertion res;
  if (r.status == del2d::InsertStatus::Duplicate || r.status == del2d::InsertStatus::Inserted) {
    res.vertex = static_cast<int>(r.vertex.index);
    res.created = r.status == del2d::InsertStatus::Inserted;
  }
  return res;
}

void BackgroundMeshKernel<2>::appendStar(int v, std::vector<TriId>& out) const {
  const VertexId vid(static_cast<std::uint32_t>(v));
  const TriId first = tri_.vertexTriangle(vid);
  if (!first.valid()) return;
  // Rotate one way (across the edge after v) until back at the start or at the boundary;
  // on the boundary, rotate the other way from the start too.
  TriId t = first;
  do {
    out.push_back(t);
    t = tri_.neighbour(t, kNext[tri_.localIndex(t, vid)]);
  } while (t.valid() && t != first);
  if (t.valid()) return;
  for (t = tri_.neighbour(first, kPrev[tri_.localIndex(first, vid)]); t.valid();
       t = tri_.neighbour(t, kPrev[tri_.localIndex(t, vid)]))
    out.push_back(t);
}

std::vector<std::array<int, 2>> BackgroundMeshKernel<2>::edgePairs() const {
  std::vector<std::array<int, 2>> pairs;
  pairs.reserve(3 * tri_.numTriangles());
  for (std::uint32_t k = 0; k < tri_.triangleSlots(); ++k) {
    const TriId t(k);
    if (!tri_.isAlive(t)) continue;
    const std::uint32_t* tv = tri_.triVertices(t);
    for (int i = 0; i < 3; ++i) {
      const TriId u = tri_.neighbour(t, i);
      if (u.valid() && u.index < k) continue;  // the edge is listed from the other side
      pairs.push_back({static_cast<int>(tv[kNext[i]]), static_cast<int>(tv[kPrev[i]])});
    }
  }
  return pairs;
}

Vec2 BackgroundMeshKernel<2>::centroid(TriId t) const {
  const Vec2& a = tri_.point(tri_.vertex(t, 0));
  const Vec2& b = tri_.point(tri_.vertex(t, 1));
  const Vec2& c = tri_.point(tri_.vertex(t, 2));
  return (a + b + c) / 3;
}

bool BackgroundMeshKernel<2>::closureContains(TriId t, const Vec2& x) const {
  const Vec2& a = tri_.point(tri_.vertex(t, 0));
  const Vec2& b = tri_.point(tri_.vertex(t, 1));
  const Vec2& c = tri_.point(tri_.vertex(t, 2));
  return predicates::orient2d(a.data(), b.data(), x.data()) >= 0 &&
         predicates::orient2d(b.data(), c.data(), x.data()) >= 0 &&
         predicates::orient2d(c.data(), a.data(), x.data()) >= 0;
}

Vec2 BackgroundMeshKernel<2>::circumcentre(TriId t) const {
  const Vec2& a = tri_.point(tri_.vertex(t, 0));
  const Vec2& b = tri_.point(tri_.vertex(t, 1));
  const Vec2& c = tri_.point(tri_.vertex(t, 2));
  const Vec2 ba = b - a, ca = c - a;
  const double d = 2 * (ba.x() * ca.y() - ba.y() * ca.x());
  const double b2 = ba.squaredNorm(), c2 = ca.squaredNorm();
  return a + Vec2(ca.y() * b2 - ba.y() * c2, ba.x() * c2 - ca.x() * b2) / d;
}

bool BackgroundMeshKernel<2>::inSphere(TriId t, const Vec2& p) const {
  const std::uint32_t* tv = tri_.triVertices(t);
  return predicates::incircle(tri_.coords(VertexId(tv[0])), tri_.coords(VertexId(tv[1])),
                              tri_.coords(VertexId(tv[2])), p.data()) > 0;
}

double BackgroundMeshKernel<2>::maxEdgeLength(TriId t, const Mat2& m) const {
  const Vec2& a = tri_.point(tri_.vertex(t, 0));
  const Vec2& b = tri_.point(tri_.vertex(t, 1));
  const Vec2& c = tri_.point(tri_.vertex(t, 2));
  return std::max({(m * (b - a)).norm(), (m * (c - b)).norm(), (m * (a - c)).norm()});
}

std::vector<std::string> BackgroundMeshKernel<2>::validate() const {
  del2d::ValidateOptions vo;
  vo.delaunay = true;
  return del2d::validate(tri_, vo);
}

}  // namespace aniso
