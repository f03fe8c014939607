#include "mesher/volume/UnfoldSurface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "mesher/core/Log.h"
#include "mesher/core/NodeBuckets.h"
#include "mesher/volume/FoldRegion.h"

namespace aniso {
namespace {

using Tri = std::array<int, 3>;

/// Flips per face, at most this many times the face's triangle count.
constexpr int kFlipsPerTriangle = 2;
/// A flip is made only where the quad is nearly flat: the volume of the tet of its four
/// nodes at most this times the cube of its longest edge (0.118 for the regular tet), so
/// that mending a fold never reshapes the surface itself.
constexpr double kMaxFlipBend = 0.01;
/// Region re-triangulations (FoldRegion.h) per face.
constexpr int kRegionRepairsPerFace = 64;

Vec3 normalOf(const SurfaceMesh& m, const Tri& t) {
  return (m.nodes[t[1]] - m.nodes[t[0]]).cross(m.nodes[t[2]] - m.nodes[t[0]]);
}

bool folded(const SurfaceMesh& m, const Tri& s, const Tri& t) {
  const Vec3 a = normalOf(m, s), b = normalOf(m, t);
  const double la = a.norm(), lb = b.norm();
  if (!(la > 0) || !(lb > 0)) return true;  // a degenerate triangle has no side
  return !(a.dot(b) >= kFoldCosine * la * lb);
}

std::pair<int, int> key(int a, int b) { return std::minmax(a, b); }

/// The triangles of one face with their edge adjacency.
class FaceTriangles {
 public:
  FaceTriangles(const SurfaceMesh& m, std::vector<Tri> tris) : m_(m), tris_(std::move(tris)) { index(); }

  const std::vector<Tri>& triangles() const { return tris_; }

  int countFolded() const {
    int n = 0;
    for (const auto& [e, list] : uses_)
      if (list.size() == 2 && folded(m_, tris_[list[0]], tris_[list[1]])) ++n;
    return n;
  }

  /// The triangle pairs on folded edges, in edge order.
  std::vector<std::vector<int>> foldedPairs() const {
    std::vector<std::vector<int>> out;
    for (const auto& [e, list] : uses_)
      if (list.size() == 2 && folded(m_, tris_[list[0]], tris_[list[1]])) out.push_back(list);
    return out;
  }

  /// One improving flip on a fold, or false when there is none.
  bool flipOnce() {
    for (const std::vector<int>& pair : foldedPairs())  // a copy: flips change uses_
      for (const int t : pair)
        for (int k = 0; k < 3; ++k)
          if (tryFlip(t, tris_[t][k], tris_[t][(k + 1) % 3])) return true;
    return false;
  }

 private:
  void index() {
    uses_.clear();
    for (int t = 0; t < static_cast<int>(tris_.size()); ++t)
      for (int k = 0; k < 3; ++k) uses_[key(tris_[t][k], tris_[t][(k + 1) % 3])].push_back(t);
  }

  void setTriangle(int t, const Tri& tri) {
    for (int k = 0; k < 3; ++k) {
      auto it = uses_.find(key(tris_[t][k], tris_[t][(k + 1) % 3]));
      it->second.erase(std::find(it->second.begin(), it->second.end(), t));
      if (it->second.empty()) uses_.erase(it);
    }
    tris_[t] = tri;
    for (int k = 0; k < 3; ++k) uses_[key(tri[k], tri[(k + 1) % 3])].push_back(t);
  }

  /// The other triangle of the face on edge (a, b), or -1.
  int across(int t, int a, int b) const {
    const auto it = uses_.find(key(a, b));
    if (it == uses_.end() || it->second.size() != 2) return -1;
    return it->second[0] == t ? it->second[1] : it->second[0];
  }

  /// Folded edges among the outer edges of the quad {s, t} (against their outer
  /// neighbours) and its diagonal, with s and t standing as given.
  int quadFolds(int s, int t, const Tri& ns, const Tri& nt) const {
    int n = folded(m_, ns, nt) ? 1 : 0;
    for (const auto& [id, tri] : {std::pair<int, const Tri&>{s, ns}, std::pair<int, const Tri&>{t, nt}})
      for (int k = 0; k < 3; ++k) {
        const int a = tri[k], b = tri[(k + 1) % 3];
        int o = across(s, a, b);
        if (o == t || o == s) o = across(t, a, b);
        if (o < 0 || o == s || o == t) continue;
        if (folded(m_, tri, tris_[o])) ++n;
      }
    return n;
  }

  bool tryFlip(int t, int a, int b) {
    const int u = across(t, a, b);
    if (u < 0) return false;
    const Tri& T = tris_[t];
    const Tri& U = tris_[u];
    int c = -1, d = -1;
    for (const int v : T)
      if (v != a && v != b) c = v;
    for (const int v : U)
      if (v != a && v != b) d = v;
    if (c < 0 || d < 0 || c == d || uses_.count(key(c, d))) return false;  // (c, d) would be doubled
    // T = (a, b, c) in its order; U runs b -> a. New: (c, a, d) and (c, d, b), same turning.
    // T = (a, b, c) and U = (b, a, d) cyclically: the quad runs a, d, b, c.
    const Tri nt = {a, d, c}, nu = {d, b, c};
    if (!(normalOf(m_, nt).norm() > 0) || !(normalOf(m_, nu).norm() > 0)) return false;
    // The quad must be nearly flat: a flip then barely moves the surface.
    const Vec3 pa = m_.nodes[a], pb = m_.nodes[b], pc = m_.nodes[c], pd = m_.nodes[d];
    const double l = std::max({(pb - pa).norm(), (pc - pa).norm(), (pd - pa).norm(), (pc - pb).norm(),
                               (pd - pb).norm(), (pd - pc).norm()});
    if (!(std::abs((pb - pa).dot((pc - pa).cross(pd - pa))) / 6.0 <= kMaxFlipBend * l * l * l)) return false;
    const int before = quadFolds(t, u, T, U);
    const Tri oldT = T, oldU = U;
    setTriangle(t, nt);
    setTriangle(u, nu);
    const int after = quadFolds(t, u, nt, nu);
    if (after < before) return true;
    setTriangle(t, oldT);
    setTriangle(u, oldU);
    return false;
  }

  const SurfaceMesh& m_;
  std::vector<Tri> tris_;
  std::map<std::pair<int, int>, std::vector<int>> uses_;
};

Tri sortedTri(Tri t) {
  std::sort(t.begin(), t.end());
  return t;
}

/// Step 2 of the header on one face: region re-triangulations of the folds left.
/// Returns the number of regions replaced; `tris` is updated.
int repairRegions(const SurfaceMesh& mesh, std::vector<Tri>& tris, std::vector<int>& useCount, std::set<Tri>& existing,
                  UnfoldStats& stats) {
  int repaired = 0;
  std::set<std::vector<Tri>> tried;
  for (int r = 0; r < kRegionRepairsPerFace; ++r) {
    bool changed = false;
    for (const std::vector<int>& pair : FaceTriangles(mesh, tris).foldedPairs()) {
      if (!tried.insert({tris[pair[0]], tris[pair[1]]}).second) continue;
      FoldRepair fix;
      if (!retriangulateFold(mesh, tris, pair, useCount, existing, fix)) continue;
      const std::set<int> gone(fix.removed.begin(), fix.removed.end());
      std::vector<Tri> kept;
      for (int t = 0; t < static_cast<int>(tris.size()); ++t) {
        if (!gone.count(t)) {
          kept.push_back(tris[t]);
          continue;
        }
        existing.erase(sortedTri(tris[t]));
        for (const int v : tris[t]) --useCount[v];
      }
      for (const Tri& t : fix.added) {
        kept.push_back(t);
        existing.insert(sortedTri(t));
        for (const int v : t) ++useCount[v];
      }
      tris = std::move(kept);
      stats.nodesDropped += fix.nodesDropped;
      ++repaired;
      changed = true;
      break;
    }
    if (!changed) break;
  }
  return repaired;
}

}  // namespace

std::vector<std::pair<int, int>> foldedEdgesByFace(const SurfaceMesh& mesh) {
  // Every triangle edge use (a < b, face, triangle), bucketed by a (NodeBuckets.h: linear),
  // each bucket sorted by (b, face, triangle): an edge of exactly two uses in one face is
  // tested with its triangles in index order, as countFoldedEdges does face by face.
  struct Use {
    int a, b, face;
    std::uint32_t tri;
  };
  std::vector<Use> uses;
  uses.reserve(3 * mesh.triangles.size());
  int highest = -1;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const auto [a, b] = key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]);
      if (a < 0) return {};  // node out of range: not a mesh to check (SurfaceMesh::validate)
      highest = std::max(highest, b);
      uses.push_back({a, b, mesh.triangleFace[t], static_cast<std::uint32_t>(t)});
    }
  NodeBuckets<Use> byNode = bucketByNode(std::span<const Use>(uses), static_cast<std::size_t>(highest + 1),
                                         [](const Use& u) { return u.a; });
  std::map<int, int> folds;
  for (std::size_t a = 0; a < byNode.nodes(); ++a) {
    const std::span<Use> bucket = byNode.bucket(a);
    std::sort(bucket.begin(), bucket.end(),
              [](const Use& x, const Use& y) { return std::tie(x.b, x.face, x.tri) < std::tie(y.b, y.face, y.tri); });
    for (std::size_t i = 0; i < bucket.size();) {
      std::size_t j = i + 1;
      while (j < bucket.size() && bucket[j].b == bucket[i].b && bucket[j].face == bucket[i].face) ++j;
      if (j - i == 2 && folded(mesh, mesh.triangles[bucket[i].tri], mesh.triangles[bucket[i + 1].tri]))
        ++folds[bucket[i].face];
      i = j;
    }
  }
  return {folds.begin(), folds.end()};
}

int countFoldedEdges(const SurfaceMesh& mesh) {
  int n = 0;
  for (const auto& [f, k] : foldedEdgesByFace(mesh)) n += k;
  return n;
}

UnfoldStats unfoldSurface(SurfaceMesh& mesh) {
  UnfoldStats stats;
  std::map<int, std::vector<int>> byFace;  // triangle indices per face, in order
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) byFace[mesh.triangleFace[t]].push_back(static_cast<int>(t));
  // The node use counts and the set of triangles, made at the first folded face (before it
  // nothing changed: the same as made here).
  std::vector<int> useCount;
  std::set<Tri> existing;
  std::map<int, std::vector<Tri>> rebuilt;  // faces whose triangle count changed
  // The faces with folds, found once (a face's repair changes only its own triangles, and
  // no node moves: the other faces' folds stay as found).
  std::set<int> foldedFaces;
  for (const auto& [f, n] : foldedEdgesByFace(mesh)) foldedFaces.insert(f);
  for (const auto& [f, ids] : byFace) {
    if (!foldedFaces.count(f)) continue;  // the common case, without FaceTriangles
    std::vector<Tri> tris;
    for (const int t : ids) tris.push_back(mesh.triangles[t]);
    if (useCount.empty()) {
      useCount.assign(mesh.nodes.size(), 0);
      for (const Tri& t : mesh.triangles) {
        existing.insert(sortedTri(t));
        for (const int v : t) ++useCount[v];
      }
    }
    FaceTriangles ft(mesh, std::move(tris));
    const int before = ft.countFolded();
    stats.foldedBefore += before;
    if (before == 0) continue;
    // 1. Flips.
    const int maxFlips = kFlipsPerTriangle * static_cast<int>(ids.size());
    int flips = 0;
    for (; flips < maxFlips && ft.flipOnce(); ++flips) ++stats.flips;
    for (const int t : ids) existing.erase(sortedTri(mesh.triangles[t]));
    for (std::size_t k = 0; k < ids.size(); ++k) {
      mesh.triangles[ids[k]] = ft.triangles()[k];
      existing.insert(sortedTri(ft.triangles()[k]));
    }
    // 2. Regions.
    std::vector<Tri> now = ft.triangles();
    const int regions = repairRegions(mesh, now, useCount, existing, stats);
    stats.regions += regions;
    const FaceTriangles left(mesh, now);
    stats.foldedAfter += left.countFolded();
    for (const std::vector<int>& pair : left.foldedPairs()) {
      std::string tris;
      for (const int t : pair)
        tris += " (" + std::to_string(now[t][0]) + ", " + std::to_string(now[t][1]) + ", " + std::to_string(now[t][2]) + ")";
      logDebug("face " + std::to_string(f + 1) + ": fold left between triangles" + tris);
    }
    if (flips > 0 || regions > 0) stats.facesChanged.push_back(f);
    if (regions > 0) rebuilt[f] = std::move(now);
  }
  if (rebuilt.empty()) return stats;
  std::vector<Tri> tris;
  std::vector<int> faces;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (rebuilt.count(mesh.triangleFace[t])) continue;
    tris.push_back(mesh.triangles[t]);
    faces.push_back(mesh.triangleFace[t]);
  }
  for (const auto& [f, list] : rebuilt)
    for (const Tri& t : list) {
      tris.push_back(t);
      faces.push_back(f);
    }
  mesh.triangles = std::move(tris);
  mesh.triangleFace = std::move(faces);
  return stats;
}

}  // namespace aniso
