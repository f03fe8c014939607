#include "mesher/volume/improve/PolyhedronReconnection.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <utility>

#include "mesher/delaunay3d/LocalRetriangulation.h"
#include "mesher/volume/TetQuality.h"

namespace aniso::improve3d {
namespace {

using del3d::TetId;
using del3d::VertexId;
using Key = std::array<std::uint32_t, 3>;   // a face's vertices, ascending
using Face = std::array<VertexId, 3>;       // oriented: its inner side is orient3d > 0
using Quad = std::array<VertexId, 4>;

Key keyOf(const Face& f) {
  Key k = {f[0].index, f[1].index, f[2].index};
  std::sort(k.begin(), k.end());
  return k;
}

/// The smallest dihedral angle of the tet (degrees, Euclidean: the referee's).
double minDihedral(const del3d::TetMesh& mesh, const Quad& q) {
  return tetMinDihedral(mesh.point(q[0]), mesh.point(q[1]), mesh.point(q[2]), mesh.point(q[3]));
}

/// The face oriented so that `inner` lies on its positive side (exact orient3d; 0: none).
bool orientTowards(const del3d::TetMesh& mesh, Face& f, VertexId inner) {
  const double o = del3d::orientation(mesh, {f[0], f[1], f[2], inner});
  if (o == 0) return false;
  if (o < 0) std::swap(f[1], f[2]);
  return true;
}

class Search {
 public:
  /// `steps`: the candidate tets tried so far, shared by the polyhedra of one call.
  Search(const del3d::TetMesh& mesh, std::vector<VertexId> vertices, double worstOld, int& steps)
      : mesh_(mesh), vertices_(std::move(vertices)), best_(worstOld), steps_(steps),
        stepLimit_(std::min(steps + kMaxReconnectionSteps, kMaxReconnectionTotalSteps)) {}

  void run(std::map<Key, Face> front) {
    front_ = std::move(front);
    descend(1e300);
  }
  bool found() const { return !bestTets_.empty(); }
  const std::vector<Quad>& tets() const { return bestTets_; }

 private:
  void descend(double worst) {
    if (front_.empty()) {
      if (worst > best_ && usesEveryVertex()) best_ = worst, bestTets_ = tets_;
      return;
    }
    if (tets_.size() >= kMaxReconnectionTets) return;
    const auto [key, f] = *front_.begin();
    // the candidates on f, best score first
    std::vector<std::pair<double, VertexId>> candidates;
    for (const VertexId p : vertices_) {
      if (p == f[0] || p == f[1] || p == f[2]) continue;
      if (++steps_ > stepLimit_) return;
      if (!(del3d::orientation(mesh_, {f[0], f[1], f[2], p}) > 0)) continue;
      const double q = minDihedral(mesh_, Quad{f[0], f[1], f[2], p});
      if (std::min(q, worst) > best_) candidates.push_back({q, p});
    }
    std::stable_sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (const auto& [q, p] : candidates) {
      if (!(std::min(q, worst) > best_)) break;  // the best found meanwhile may prune the rest
      place(f, key, p, std::min(q, worst));
    }
  }

  /// The tet (f, p) placed when its faces fit the front, then the search goes on; undone.
  void place(const Face& f, const Key& key, VertexId p, double worst) {
    // its three other faces, each with the vertex opposite it
    const std::array<std::pair<Face, VertexId>, 3> sides = {{{{f[0], f[1], p}, f[2]}, {{f[1], f[2], p}, f[0]}, {{f[2], f[0], p}, f[1]}}};
    std::vector<std::pair<Key, Face>> closing;
    std::vector<std::pair<Key, Face>> opening;
    for (const auto& [g, opposite] : sides) {
      const Key k = keyOf(g);
      if (closed_.count(k)) return;
      const auto it = front_.find(k);
      if (it != front_.end()) {  // an open face: the tet must lie on its inner side
        if (!(del3d::orientation(mesh_, {it->second[0], it->second[1], it->second[2], opposite}) > 0)) return;
        closing.push_back(*it);
      } else {  // a new open face, its inner side away from the tet
        Face h = g;
        if (!orientTowards(mesh_, h, opposite)) return;
        std::swap(h[1], h[2]);
        opening.push_back({k, h});
      }
    }
    const Face fKept = f;
    front_.erase(key);
    closed_.insert(key);
    for (const auto& [k, h] : closing) {
      front_.erase(k);
      closed_.insert(k);
    }
    for (const auto& [k, h] : opening) front_.emplace(k, h);
    tets_.push_back({fKept[0], fKept[1], fKept[2], p});
    descend(worst);
    tets_.pop_back();
    for (const auto& [k, h] : opening) front_.erase(k);
    for (const auto& [k, h] : closing) {
      closed_.erase(k);
      front_.emplace(k, h);
    }
    closed_.erase(key);
    front_.emplace(key, fKept);
  }

  bool usesEveryVertex() const {
    for (const VertexId v : vertices_)
      if (std::none_of(tets_.begin(), tets_.end(), [&](const Quad& q) { return std::find(q.begin(), q.end(), v) != q.end(); }))
        return false;
    return true;
  }

  const del3d::TetMesh& mesh_;
  std::vector<VertexId> vertices_;
  double best_;
  std::vector<Quad> bestTets_, tets_;
  std::map<Key, Face> front_;
  std::set<Key> closed_;
  int& steps_;
  int stepLimit_;
};

/// The polyhedron: its tets and their vertices.
struct Polyhedron {
  std::vector<TetId> tets;
  std::vector<VertexId> vertices;
  bool has(TetId u) const { return std::find(tets.begin(), tets.end(), u) != tets.end(); }
  bool hasVertex(VertexId v) const { return std::find(vertices.begin(), vertices.end(), v) != vertices.end(); }
  void add(const del3d::TetMesh& mesh, TetId u) {
    tets.push_back(u);
    for (int i = 0; i < 4; ++i)
      if (!hasVertex(mesh.vertex(u, i))) vertices.push_back(mesh.vertex(u, i));
  }
  /// Adds the tets across unconstrained faces whose vertices are all in it, while it may
  /// grow (bounded: each pass adds a tet or stops).
  void close(const del3d::TetMesh& mesh) {
    for (bool grew = true; grew && tets.size() < kMaxReconnectionTets;) {
      grew = false;
      for (std::size_t c = 0; c < tets.size() && !grew; ++c)
        for (int i = 0; i < 4 && !grew; ++i) {
          const TetId n = mesh.neighbour(tets[c], i);
          if (!n.valid() || mesh.isConstrained(tets[c], i) || has(n)) continue;
          bool inside = true;
          for (int k = 0; k < 4; ++k) inside = inside && hasVertex(mesh.vertex(n, k));
          if (inside) add(mesh, n), grew = true;
        }
    }
  }
};

/// The best tetrahedralization of p better than its worst tet (empty: none).
std::vector<Quad> bestTetrahedralization(const del3d::TetMesh& mesh, const Polyhedron& p, int& steps) {
  // the boundary of the union, each face oriented towards its tet; a constrained face
  // inside it stays (no reconnection)
  std::map<Key, std::pair<Face, int>> faces;
  for (const TetId u : p.tets)
    for (int i = 0; i < 4; ++i) {
      Face f = {mesh.vertex(u, del3d::kFaceVertex[i][0]), mesh.vertex(u, del3d::kFaceVertex[i][1]),
                mesh.vertex(u, del3d::kFaceVertex[i][2])};
      if (!orientTowards(mesh, f, mesh.vertex(u, i))) return {};
      auto& entry = faces[keyOf(f)];
      entry.first = f;
      if (++entry.second == 2 && mesh.isConstrained(u, i)) return {};
    }
  std::map<Key, Face> front;
  for (const auto& [k, e] : faces)
    if (e.second == 1) front.emplace(k, e.first);
  double worstOld = 1e300;
  for (const TetId u : p.tets) worstOld = std::min(worstOld, tetMinDihedral(mesh, u));
  std::vector<VertexId> vertices = p.vertices;
  std::sort(vertices.begin(), vertices.end(), [](VertexId a, VertexId b) { return a.index < b.index; });
  Search search(mesh, vertices, worstOld, steps);
  search.run(front);
  return search.found() ? search.tets() : std::vector<Quad>{};
}

}  // namespace

bool reconnectPolyhedron(SolidTetMesh& s, TetId t, std::vector<TetId>& created) {
  const del3d::TetMesh& mesh = s.mesh;
  if (!mesh.isAlive(t)) return false;
  Polyhedron base;
  base.add(mesh, t);
  for (int i = 0; i < 4; ++i) {
    const TetId n = mesh.neighbour(t, i);
    if (n.valid() && !mesh.isConstrained(t, i) && !base.has(n)) base.add(mesh, n);
  }
  if (base.vertices.size() > kMaxReconnectionVertices) return false;
  base.close(mesh);
  // the polyhedron, then (when it has no better tetrahedralization) it grown by the tet
  // across one of its unconstrained faces, then by one more: breadth first, each once
  std::vector<Polyhedron> tries = {base};
  const auto sortedTets = [](const Polyhedron& p) {
    std::vector<std::uint32_t> ids;
    for (const TetId u : p.tets) ids.push_back(u.index);
    std::sort(ids.begin(), ids.end());
    return ids;
  };
  std::set<std::vector<std::uint32_t>> seen = {sortedTets(base)};
  for (std::size_t level = 0, from = 0; level < kMaxReconnectionGrowths; ++level) {
    const std::size_t to = tries.size();
    for (std::size_t k = from; k < to; ++k)
      for (std::size_t c = 0; c < tries[k].tets.size(); ++c)
        for (int i = 0; i < 4; ++i) {
          const TetId u = tries[k].tets[c], n = mesh.neighbour(u, i);
          if (!n.valid() || mesh.isConstrained(u, i) || tries[k].has(n) || tries.size() >= kMaxReconnectionTries ||
              tries[k].tets.size() >= kMaxReconnectionTets)
            continue;
          Polyhedron p = tries[k];
          p.add(mesh, n);
          if (p.vertices.size() > kMaxReconnectionVertices) continue;
          p.close(mesh);
          if (seen.insert(sortedTets(p)).second) tries.push_back(std::move(p));
        }
    from = to;
  }
  int steps = 0;
  for (std::size_t k = 0; k < tries.size() && steps < kMaxReconnectionTotalSteps; ++k) {
    const std::vector<Quad> tets = bestTetrahedralization(mesh, tries[k], steps);
    if (tets.empty()) continue;
    std::vector<TetId> ids(tets.size());
    del3d::replaceTets(s.mesh, tries[k].tets, tets, ids);
    created.insert(created.end(), ids.begin(), ids.end());
    return true;
  }
  return false;
}

}  // namespace aniso::improve3d
