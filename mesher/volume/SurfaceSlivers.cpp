#include "mesher/volume/SurfaceSlivers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "mesher/core/Error.h"
#include "mesher/model/EdgeNormals.h"
#include "mesher/surface/MidEdgeGeometry.h"
#include "mesher/volume/FoldRegion.h"

namespace aniso {
namespace {

using Tri = std::array<int, 3>;

const double kCapCosine = std::cos(kCapAngleDeg * std::numbers::pi / 180);
/// Cosine margin of the fold test of a cap flip (the new triangles turn by up to
/// kCapFlipTurnDeg from (a, b, d)).
constexpr double kFoldSlack = 0.15;
const double kTurnCosine = std::cos(kCapFlipTurnDeg * std::numbers::pi / 180);

std::uint64_t edgeKey(int a, int b) {
  const auto [lo, hi] = std::minmax(a, b);
  return (static_cast<std::uint64_t>(lo) << 32) | static_cast<std::uint32_t>(hi);
}

/// 0 for a CAD vertex node, 1 for an edge node, 2 for a face node: the lower is kept.
int rank(const NodeOn& on) {
  return on.kind == NodeOn::Kind::Vertex ? 0 : on.kind == NodeOn::Kind::Edge ? 1 : 2;
}

/// The corner of t with an angle above kCapAngleDeg, or -1.
int capCorner(const SurfaceMesh& m, const Tri& t) {
  for (int k = 0; k < 3; ++k) {
    const Vec3 u = m.nodes[t[(k + 1) % 3]] - m.nodes[t[k]], v = m.nodes[t[(k + 2) % 3]] - m.nodes[t[k]];
    const double nu = u.norm(), nv = v.norm();
    if (nu > 0 && nv > 0 && u.dot(v) < kCapCosine * nu * nv) return k;
  }
  return -1;
}

/// Triangle indices, ascending: those using one mesh edge or one node (empty: none).
struct TriRange {
  const int* first = nullptr;
  const int* last = nullptr;
  const int* begin() const { return first; }
  const int* end() const { return last; }
  std::size_t size() const { return static_cast<std::size_t>(last - first); }
  bool empty() const { return first == last; }
  int operator[](std::size_t i) const { return first[i]; }
};

class SliverPass {
 public:
  // The adjacency is built once per pass in flat arrays (a pass over a 2.2 M triangle
  // surface rebuilt a hash map of vectors, half its time in malloc) and not updated within
  // the pass: an operation only touches triangles none of whose nodes changed (dirty_).
  // The first pass looks at every triangle. A later one (`previous`: the nodes the pass
  // before changed) looks only at the triangles with a node within one edge of such a
  // node: whether an operation is legal depends on the triangle, the stars of its nodes
  // and the triangles across its edges, all unchanged elsewhere since they were last
  // refused — so the result is the full pass's. Its adjacency holds the triangles it can
  // reach from those (the stars of their nodes).
  SliverPass(SurfaceMesh& m, double tolerance, const MidEdgeGeometry* geo, const std::vector<std::uint8_t>& filmRim,
             SurfaceSliverStats& stats, const std::vector<std::uint8_t>* previous, int keepFrom)
      : m_(m), tol_(tolerance), geo_(geo), filmRim_(filmRim), stats_(stats), keepFrom_(keepFrom),
        dirty_(m.nodes.size(), 0) {
    const int nt = static_cast<int>(m.triangles.size());
    std::vector<int> known;  // the triangles in the adjacency, ascending
    if (!previous) {
      scan_.resize(static_cast<std::size_t>(nt));
      for (int t = 0; t < nt; ++t) scan_[static_cast<std::size_t>(t)] = t;
      known = scan_;
    } else {
      // grow the node marks one ring at a time: dirty -> near (1 ring) -> star nodes of
      // the scanned triangles; each ring is one sweep over the triangles
      std::vector<std::uint8_t> mark = *previous;
      const auto grow = [&](std::vector<int>* hit) {
        std::vector<std::uint8_t> next = mark;
        for (int t = 0; t < nt; ++t) {
          const Tri& tri = m.triangles[static_cast<std::size_t>(t)];
          if (!mark[tri[0]] && !mark[tri[1]] && !mark[tri[2]]) continue;
          if (hit) hit->push_back(t);
          for (const int v : tri) next[static_cast<std::size_t>(v)] = 1;
        }
        mark = std::move(next);
      };
      grow(nullptr);  // mark: the nodes within one edge of a changed node
      grow(&scan_);   // scan_: the triangles using them; mark: their nodes
      grow(&known);   // known: the triangles using those (every star the operations read)
    }
    std::vector<std::pair<std::uint64_t, int>> edges;
    edges.reserve(3 * known.size());
    nodeStart_.assign(m.nodes.size() + 1, 0);
    for (const int t : known)
      for (int k = 0; k < 3; ++k) {
        edges.push_back({edgeKey(m.triangles[t][k], m.triangles[t][(k + 1) % 3]), t});
        ++nodeStart_[static_cast<std::size_t>(m.triangles[t][k]) + 1];
      }
    std::sort(edges.begin(), edges.end());
    edgeKeys_.reserve(edges.size());
    edgeTris_.reserve(edges.size());
    for (const auto& [key, t] : edges) {
      edgeKeys_.push_back(key);
      edgeTris_.push_back(t);
    }
    for (std::size_t v = 1; v < nodeStart_.size(); ++v) nodeStart_[v] += nodeStart_[v - 1];
    nodeTriList_.resize(static_cast<std::size_t>(nodeStart_.back()));
    std::vector<int> fill(nodeStart_.begin(), nodeStart_.end() - 1);
    for (const int t : known)
      for (int k = 0; k < 3; ++k) nodeTriList_[static_cast<std::size_t>(fill[static_cast<std::size_t>(m.triangles[t][k])]++)] = t;
    removed_.assign(m.triangles.size(), 0);
  }

  /// The nodes in a triangle this pass changed (for the next pass's scope).
  const std::vector<std::uint8_t>& changedNodes() const { return dirty_; }

  /// One pass over the triangles; true when something changed (the mesh is compacted).
  bool run() {
    bool changed = false;
    for (const int t : scan_) {
      if (removed_[t]) continue;
      for (int k = 0; k < 3 && !removed_[t]; ++k) {
        const int a = m_.triangles[t][k], c = m_.triangles[t][(k + 1) % 3];
        const double length = (m_.nodes[a] - m_.nodes[c]).norm();
        if ((length <= tol_ || (length <= localTolerance(edgeSize(a, c)) && !acrossFilmRim(a, c))) && merge(a, c))
          changed = true;
      }
      if (removed_[t]) continue;
      const int k = capVertex(m_.triangles[t]);
      if (k >= 0 && flip(t, k)) changed = true;
    }
    if (changed) compact();
    return changed;
  }

 private:
  Vec3 normal(const Tri& t) const {
    return (m_.nodes[t[1]] - m_.nodes[t[0]]).cross(m_.nodes[t[2]] - m_.nodes[t[0]]);
  }

  int capVertex(const Tri& t) const { return capCorner(m_, t); }

  double longestEdge(const Tri& t) const {
    double l = 0;
    for (int k = 0; k < 3; ++k) l = std::max(l, (m_.nodes[t[k]] - m_.nodes[t[(k + 1) % 3]]).norm());
    return l;
  }

  /// The local size at the edge (a, b): the smallest longest edge of its triangles.
  double edgeSize(int a, int b) const {
    double size = 1e300;
    for (const int t : uses(a, b)) size = std::min(size, longestEdge(m_.triangles[t]));
    return size;
  }

  /// How far the surface may move at a triangle whose longest edge is `size` (header).
  double localTolerance(double size) const { return std::max(tol_, kLocalSliverRatio * size); }

  double minAngle(const Tri& t) const {
    double best = 1e300;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = m_.nodes[t[(k + 1) % 3]] - m_.nodes[t[k]], v = m_.nodes[t[(k + 2) % 3]] - m_.nodes[t[k]];
      best = std::min(best, std::atan2(u.cross(v).norm(), u.dot(v)));
    }
    return best;
  }

  TriRange uses(int a, int b) const {
    const std::uint64_t key = edgeKey(a, b);
    const auto lo = std::lower_bound(edgeKeys_.begin(), edgeKeys_.end(), key);
    const auto hi = std::upper_bound(lo, edgeKeys_.end(), key);
    const int* base = edgeTris_.data();
    return {base + (lo - edgeKeys_.begin()), base + (hi - edgeKeys_.begin())};
  }

  TriRange nodeTris(int v) const {
    const int* base = nodeTriList_.data();
    return {base + nodeStart_[static_cast<std::size_t>(v)], base + nodeStart_[static_cast<std::size_t>(v) + 1]};
  }

  /// The other triangle on the manifold edge (a, b), or -1.
  int across(int t, int a, int b) const {
    const TriRange u = uses(a, b);
    if (u.size() != 2) return -1;
    return u[0] == t ? u[1] : u[0];
  }

  /// Distance of the mesh edge (a, b) of face f from the CAD (its midpoint from the
  /// mid node MidEdgeGeometry places).
  double deviation(int a, int b, int f) const {
    return (geo_->place(a, b, f).p - 0.5 * (m_.nodes[a] + m_.nodes[b])).norm();
  }

  bool clean(const Tri& t) const { return !dirty_[t[0]] && !dirty_[t[1]] && !dirty_[t[2]]; }

  bool onFilmRim(int t) const {
    const int f = m_.triangleFace[static_cast<std::size_t>(t)];
    return f >= 0 && static_cast<std::size_t>(f) < filmRim_.size() && filmRim_[static_cast<std::size_t>(f)];
  }

  /// Every triangle on (a, b) lies on a film's rim (header: the edge spans the film).
  bool acrossFilmRim(int a, int b) const {
    const TriRange u = uses(a, b);
    return !u.empty() && std::all_of(u.begin(), u.end(), [&](int t) { return onFilmRim(t); });
  }

  void touch(int t) {
    for (const int v : m_.triangles[t]) dirty_[v] = 1;
    stats_.facesChanged.push_back(m_.triangleFace[t]);
  }

  bool merge(int a, int c);
  bool collapse(int a, int c);
  bool flip(int t, int k);
  void compact();

  SurfaceMesh& m_;
  double tol_;
  const MidEdgeGeometry* geo_;
  const std::vector<std::uint8_t>& filmRim_;  ///< per model face: a film's rim (EdgeNormals.h)
  SurfaceSliverStats& stats_;
  int keepFrom_;  ///< nodes from this index on are never removed by a merge
  bool kept(int v) const { return keepFrom_ >= 0 && v >= keepFrom_; }
  std::vector<int> scan_;                ///< the triangles the pass looks at, ascending
  std::vector<std::uint64_t> edgeKeys_;  ///< sorted (edge key, triangle): the keys ...
  std::vector<int> edgeTris_;            ///< ... and the triangles
  std::vector<int> nodeStart_;           ///< per node, its first entry in nodeTriList_
  std::vector<int> nodeTriList_;
  std::vector<std::uint8_t> dirty_;  ///< per node: in a triangle changed in this pass
  std::vector<std::uint8_t> removed_;
};

// Collapse of (a, c) into the more constrained node, or either of two alike (header,
// operation 1).
bool SliverPass::merge(int a, int c) {
  if (rank(m_.nodeOn[c]) < rank(m_.nodeOn[a]) || (rank(m_.nodeOn[c]) == rank(m_.nodeOn[a]) && c < a)) std::swap(a, c);
  if (!kept(c) && collapse(a, c)) return true;
  return rank(m_.nodeOn[c]) == rank(m_.nodeOn[a]) && !kept(a) && collapse(c, a);
}

// c moved onto a (rank(c) >= rank(a)), when legal (header, operation 1).
bool SliverPass::collapse(int a, int c) {
  const TriRange ac = uses(a, c);
  if (ac.size() != 2) return false;
  for (const int v : {a, c})
    for (const int t : nodeTris(v))
      if (!clean(m_.triangles[t])) return false;
  // link condition: a and c share exactly the two opposite nodes of (a, c)
  std::vector<int> opposite, linkA, linkC;
  for (const int t : ac)
    for (const int v : m_.triangles[t])
      if (v != a && v != c) opposite.push_back(v);
  for (const auto& [v, link] : {std::pair<int, std::vector<int>*>{a, &linkA}, {c, &linkC}})
    for (const int t : nodeTris(v))
      for (const int w : m_.triangles[t])
        if (w != a && w != c) link->push_back(w);
  for (auto* l : {&linkA, &linkC, &opposite}) {
    std::sort(l->begin(), l->end());
    l->erase(std::unique(l->begin(), l->end()), l->end());
  }
  std::vector<int> shared;
  std::set_intersection(linkA.begin(), linkA.end(), linkC.begin(), linkC.end(), std::back_inserter(shared));
  if (shared != opposite || opposite.size() != 2) return false;
  // every edge at c manifold; moved triangles keep a non-zero area and their side
  for (const int t : nodeTris(c)) {
    const Tri& tri = m_.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] == c || tri[(k + 1) % 3] == c) {
        if (uses(tri[k], tri[(k + 1) % 3]).size() != 2) return false;
      }
    if (std::find(ac.begin(), ac.end(), t) != ac.end()) continue;
    Tri moved = tri;
    std::replace(moved.begin(), moved.end(), c, a);
    const Vec3 before = normal(tri), after = normal(moved);
    if (!(after.norm() > 0) || !(after.dot(before) > 0)) return false;
  }
  for (const int t : nodeTris(a)) touch(t);
  for (const int t : nodeTris(c)) {
    touch(t);
    if (std::find(ac.begin(), ac.end(), t) != ac.end())
      removed_[t] = 1;
    else
      std::replace(m_.triangles[t].begin(), m_.triangles[t].end(), c, a);
  }
  ++stats_.nodesMerged;
  return true;
}

// Flip of the edge opposite the cap's corner k (header, operation 2).
bool SliverPass::flip(int t, int k) {
  const Tri T = m_.triangles[t];
  const int c = T[k], a = T[(k + 1) % 3], b = T[(k + 2) % 3];
  const int u = across(t, a, b);
  if (u < 0 || !clean(T) || !clean(m_.triangles[u])) return false;
  const Tri U = m_.triangles[u];
  int d = -1;
  for (const int v : U)
    if (v != a && v != b) d = v;
  if (d < 0 || d == c || !uses(c, d).empty()) return false;
  // c within the tolerance of the plane of (a, b, d), or (inside one face) the new edge
  // nearer the CAD surface than the old one
  const Vec3 nu = normal(U);
  if (!(nu.norm() > 0)) return false;
  const bool offRim = onFilmRim(t) && m_.triangleFace[t] != m_.triangleFace[u];  // a rim's node onto the film's side
  const double planeTolerance = offRim ? tol_ : localTolerance((m_.nodes[a] - m_.nodes[b]).norm());
  if (std::abs(nu.dot(m_.nodes[c] - m_.nodes[a])) > planeTolerance * nu.norm()) {
    const int f = m_.triangleFace[u];
    if (!geo_ || m_.triangleFace[t] != f || !(deviation(c, d, f) < deviation(a, b, f))) return false;
  }
  // T = (c, a, b), U = (b, a, d): the quad c, a, d, b; its other diagonal (c, d)
  const Tri n1 = {c, a, d}, n2 = {c, d, b};
  for (const Tri& n : {n1, n2}) {
    const Vec3 nn = normal(n);
    if (!(nn.norm() > 0) || nn.dot(nu) < kTurnCosine * nn.norm() * nu.norm()) return false;
  }
  // no new fold against the outer neighbours: each new triangle meets them no sharper than
  // (a, b, d) did, or than kFoldCosine (a cap's normal says nothing: neither the old
  // triangle's nor a neighbour cap's counts)
  struct Outer {
    int x, y, from;
    const Tri* now;
  };
  const Outer outer[4] = {{c, a, t, &n1}, {a, d, u, &n1}, {d, b, u, &n2}, {b, c, t, &n2}};
  for (const Outer& e : outer) {
    const int o = across(e.from, e.x, e.y);
    if (o < 0 || capVertex(m_.triangles[o]) >= 0) continue;
    const Vec3 nn = normal(*e.now), no = normal(m_.triangles[o]);
    const double before = nu.dot(no) / (nu.norm() * no.norm());
    if (nn.dot(no) < (std::min(before, kFoldCosine) - kFoldSlack) * nn.norm() * no.norm()) return false;
  }
  if (!(std::min(minAngle(n1), minAngle(n2)) > std::min(minAngle(T), minAngle(U)))) return false;
  touch(t);
  touch(u);
  m_.triangles[t] = n1;
  m_.triangles[u] = n2;
  m_.triangleFace[t] = m_.triangleFace[u];
  touch(t);
  ++stats_.capsFlipped;
  return true;
}

void SliverPass::compact() {
  std::size_t n = 0;
  for (std::size_t t = 0; t < m_.triangles.size(); ++t)
    if (!removed_[t]) {
      m_.triangles[n] = m_.triangles[t];
      m_.triangleFace[n] = m_.triangleFace[t];
      ++n;
    }
  m_.triangles.resize(n);
  m_.triangleFace.resize(n);
}

}  // namespace

SurfaceSliverStats mendSurfaceSlivers(SurfaceMesh& mesh, double tolerance, const Model* model, int keepFrom) {
  SurfaceSliverStats stats;
  if (!mesh.quads.empty() || !mesh.triangleMid.empty() || !(tolerance > 0)) return stats;
  // Nothing a pass would act on (no edge within the tolerance, no cap: the common case):
  // done, without the pass's adjacency and the CAD geometry.
  const auto actsOn = [&](const Tri& t) {
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, (mesh.nodes[t[k]] - mesh.nodes[t[(k + 1) % 3]]).norm());
    for (int k = 0; k < 3; ++k)
      if ((mesh.nodes[t[k]] - mesh.nodes[t[(k + 1) % 3]]).norm() <= std::max(tolerance, kLocalSliverRatio * longest))
        return true;
    return capCorner(mesh, t) >= 0;
  };
  if (std::none_of(mesh.triangles.begin(), mesh.triangles.end(), actsOn)) return stats;
  // the model edges' discretisations it indexes keep their nodes (merged nodes stay in
  // the node array)
  std::optional<MidEdgeGeometry> geo;
  if (model) {
    try {
      geo.emplace(*model, mesh);
    } catch (const MeshingError&) {
      geo.reset();  // nodes on entities the model lacks (hand-made meshes): no CAD test
    }
  }
  const std::vector<std::uint8_t> filmRim = geo ? filmRims(*model) : std::vector<std::uint8_t>{};
  std::vector<std::uint8_t> changed;
  for (int pass = 0; pass < kMaxSliverPasses; ++pass) {
    SliverPass p(mesh, tolerance, geo ? &*geo : nullptr, filmRim, stats, pass == 0 ? nullptr : &changed, keepFrom);
    if (!p.run()) break;
    changed = p.changedNodes();
  }
  std::sort(stats.facesChanged.begin(), stats.facesChanged.end());
  stats.facesChanged.erase(std::unique(stats.facesChanged.begin(), stats.facesChanged.end()), stats.facesChanged.end());
  return stats;
}

int countSurfaceCaps(const SurfaceMesh& mesh) {
  return static_cast<int>(
      std::count_if(mesh.triangles.begin(), mesh.triangles.end(), [&](const Tri& t) { return capCorner(mesh, t) >= 0; }));
}

}  // namespace aniso
