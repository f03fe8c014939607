#include "mesher/volume/improve/SliverSteinerPoint.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "mesher/delaunay3d/EdgeRing.h"
#include "mesher/delaunay3d/LocalRetriangulation.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::improve3d {
namespace {

using del3d::TetId;
using del3d::VertexId;

/// A region around the sliver: its tets and the tets of the star of p replacing them.
struct Region {
  std::vector<TetId> tets;
  std::vector<std::array<std::uint32_t, 4>> cone;  ///< new tets, p written as kNewVertex
  double oldWorst = 1e300;
};

constexpr std::uint32_t kNewVertex = 0xFFFFFFFFu;
constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/// Builds the region of the given tets; false when its boundary has more faces than
/// kMaxLocalTets or a vertex of it would vanish.
bool buildRegion(const SolidTetMesh& s, const VertexMetrics& vm, const std::vector<TetId>& tets, Region& r) {
  const del3d::TetMesh& m = s.mesh;
  r.tets = tets;
  r.cone.clear();
  r.oldWorst = 1e300;
  const auto inRegion = [&](TetId u) { return std::find(r.tets.begin(), r.tets.end(), u) != r.tets.end(); };
  for (const TetId u : r.tets) {
    r.oldWorst = std::min(r.oldWorst, vm.score(u));
    for (int f = 0; f < 4; ++f) {
      const TetId n = m.neighbour(u, f);
      if (n.valid() && inRegion(n)) continue;
      std::array<std::uint32_t, 4> q;
      std::copy_n(m.tetVertices(u), 4, q.begin());
      q[f] = kNewVertex;
      r.cone.push_back(q);
    }
  }
  if (r.cone.size() > del3d::kMaxLocalTets) return false;
  for (const TetId u : r.tets)
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t v = m.tetVertices(u)[i];
      const bool kept = std::any_of(r.cone.begin(), r.cone.end(),
                                    [&](const auto& q) { return std::find(q.begin(), q.end(), v) != q.end(); });
      if (!kept) return false;
    }
  return true;
}

/// Worst score of the cone with p at `p` (tensor mp), or -1e300 when a tet is not
/// positively oriented.
double coneScore(const SolidTetMesh& s, const VertexMetrics& vm, const Region& r, const Vec3& p, const Mat3& mp,
                 bool isoP) {
  const double xyz[3] = {p.x(), p.y(), p.z()};
  double worst = 1e300;
  for (const auto& q : r.cone) {
    const double* c[4];
    Vec3 x[4];
    Mat3 tensor = 0.25 * mp;
    bool iso = isoP;
    for (int i = 0; i < 4; ++i) {
      if (q[i] == kNewVertex) {
        c[i] = xyz;
        x[i] = p;
        continue;
      }
      const VertexId v(q[i]);
      c[i] = s.mesh.coords(v);
      x[i] = s.mesh.point(v);
      tensor += 0.25 * vm.at(v);
      iso = iso && vm.isIsotropic(v);
    }
    if (predicates::orient3d(c[0], c[1], c[2], c[3]) <= 0) return -1e300;
    worst = std::min(worst, vm.scorePoints(x, tensor, iso));
  }
  return worst;
}

/// Unit normal of face f of t towards vertex f (into the solid when f is a hull face);
/// zero for a degenerate face.
Vec3 hullInwardNormal(const del3d::TetMesh& m, TetId t, int f) {
  const Vec3 a = m.point(m.vertex(t, del3d::kFaceVertex[f][0])), b = m.point(m.vertex(t, del3d::kFaceVertex[f][1])),
             c = m.point(m.vertex(t, del3d::kFaceVertex[f][2]));
  Vec3 n = (b - a).cross(c - a);
  if (!(n.norm() > 0)) return Vec3::Zero();
  if (n.dot(m.point(m.vertex(t, f)) - a) < 0) n = -n;
  return n.normalized();
}

void candidatePoints(const SolidTetMesh& s, TetId t, const Region& r, std::vector<Vec3>& out) {
  const del3d::TetMesh& m = s.mesh;
  out.clear();
  Vec3 ct = Vec3::Zero();
  for (int i = 0; i < 4; ++i) ct += 0.25 * m.point(m.vertex(t, i));
  Vec3 cr = Vec3::Zero();
  for (const TetId u : r.tets)
    for (int i = 0; i < 4; ++i) cr += m.point(m.vertex(u, i)) / (4.0 * static_cast<double>(r.tets.size()));
  out.push_back(ct);
  out.push_back(cr);
  out.push_back(0.5 * (ct + cr));
  for (int f = 0; f < 4; ++f) {
    if (m.neighbour(t, f).valid() && !m.isConstrained(t, f)) continue;  // a hull or embedded face: the tet lies on vertex f's side
    const Vec3 a = m.point(m.vertex(t, del3d::kFaceVertex[f][0])), b = m.point(m.vertex(t, del3d::kFaceVertex[f][1])),
               c = m.point(m.vertex(t, del3d::kFaceVertex[f][2]));
    const Vec3 n = hullInwardNormal(m, t, f);
    if (n == Vec3::Zero()) continue;
    const double len = ((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3;
    for (const double h : kApexHeights) out.push_back((a + b + c) / 3 + h * len * n);
  }
}

}  // namespace

VertexId insertSteinerPointAtSliver(SolidTetMesh& s, VertexMetrics& vm, TetId t, std::vector<TetId>& created) {
  if (!s.mesh.isAlive(t)) return VertexId();
  const std::uint32_t* tv = s.mesh.tetVertices(t);
  const Mat3 mp = vm.tetMetric(tv);
  bool isoP = true;
  for (int i = 0; i < 4; ++i) isoP = isoP && vm.isIsotropic(VertexId(tv[i]));
  Region r, best;
  Vec3 bestP = Vec3::Zero();
  double bestScore = -1e300;
  std::vector<Vec3> points;
  const auto tryRegion = [&](const std::vector<TetId>& tets, const Vec3* extra, int nExtra) {
    if (!buildRegion(s, vm, tets, r)) return;
    candidatePoints(s, t, r, points);
    points.insert(points.end(), extra, extra + nExtra);
    for (const Vec3& p : points) {
      const double sc = coneScore(s, vm, r, p, mp, isoP);
      if (sc > r.oldWorst && sc > bestScore) bestScore = sc, bestP = p, best = r;
    }
  };
  // (a) t and a subset of its neighbours across its interior faces, smallest first
  std::array<TetId, 4> nbr;
  unsigned valid = 0;
  for (int i = 0; i < 4; ++i) {
    nbr[i] = s.mesh.neighbour(t, i);
    if (nbr[i].valid()) valid |= 1u << i;
  }
  std::vector<TetId> tets;
  for (int size = 0; size <= kMaxRegionNeighbours; ++size)
    for (unsigned mask = 0; mask < 16; ++mask) {
      if ((mask & ~valid) != 0 || std::popcount(mask) != size) continue;
      tets.assign(1, t);
      for (int i = 0; i < 4; ++i)
        if (mask & (1u << i)) tets.push_back(nbr[i]);
      tryRegion(tets, nullptr, 0);
    }
  // (b) the ring of an interior edge of t (the edge split at p): the midpoint, and points
  // between it and the centroid of the ring
  del3d::EdgeRing ring;
  for (const auto& e : kEdge) {
    del3d::edgeRing(s.mesh, t, e[0], e[1], ring);
    if (!ring.closed || 2 * ring.tets.size() > del3d::kMaxLocalTets) continue;
    const Vec3 mid = 0.5 * (s.mesh.point(ring.a) + s.mesh.point(ring.b));
    Vec3 c = Vec3::Zero();
    for (const VertexId w : ring.apex) c += s.mesh.point(w) / static_cast<double>(ring.apex.size());
    const Vec3 extra[3] = {mid, mid + 0.25 * (c - mid), mid + 0.5 * (c - mid)};
    tryRegion(ring.tets, extra, 3);
  }
  if (best.tets.empty()) return VertexId();
  const VertexId v = s.addFreeVertex(bestP);
  vm.sync();
  std::vector<std::array<VertexId, 4>> quads;
  for (const auto& q : best.cone) {
    std::array<VertexId, 4> x;
    for (int i = 0; i < 4; ++i) x[i] = q[i] == kNewVertex ? v : VertexId(q[i]);
    quads.push_back(x);
  }
  std::vector<TetId> ids(quads.size());
  del3d::replaceTets(s.mesh, best.tets, quads, ids);
  created.insert(created.end(), ids.begin(), ids.end());
  return v;
}

}  // namespace aniso::improve3d
