#include "mesher/quad/TriangleTransport.h"

#include <algorithm>
#include <array>
#include <deque>

#include "mesher/quad/ChainQuadrangulation.h"
#include "mesher/quad/HexagonSplit.h"
#include "mesher/quad/PairSplit.h"

namespace aniso::quad {
namespace {

/// Shortest paths of elements (by adjacency) from triangle t to the nearest other live
/// triangles (up to maxTargets of them, nearest first), both ends included: the partners,
/// nearest first.
std::vector<std::vector<int>> pathsToTriangles(const QuadMesh2d& mesh, int t, int maxLength, int maxTargets) {
  std::vector<int> from(mesh.numElements(), -2), depth(mesh.numElements(), 0);
  std::deque<int> queue{t};
  std::vector<std::vector<int>> paths;
  from[t] = -1;
  while (!queue.empty() && static_cast<int>(paths.size()) < maxTargets) {
    const int e = queue.front();
    queue.pop_front();
    if (e != t && mesh.isTriangle(e)) {
      std::vector<int> path;
      for (int x = e; x != -1; x = from[x]) path.push_back(x);
      std::reverse(path.begin(), path.end());
      paths.push_back(std::move(path));
      continue;  // paths do not run through other triangles
    }
    if (depth[e] >= maxLength) continue;
    const int n = mesh.sides(e);
    for (int k = 0; k < n; ++k) {
      const int f = mesh.adj[e][k];
      if (f == kNone || from[f] != -2) continue;
      from[f] = e;
      depth[f] = depth[e] + 1;
      queue.push_back(f);
    }
  }
  return paths;
}

int sharedEdge(const QuadMesh2d& mesh, int e, int f) {
  for (int k = 0; k < mesh.sides(e); ++k)
    if (mesh.adj[e][k] == f) return k;
  return kNone;
}

class Transport {
 public:
  Transport(QuadMesh2d& mesh, VertexMetrics& metrics, const TransportOptions& o)
      : mesh_(mesh), metrics_(metrics), o_(o) {}

  Vec2 centroid(int e) const {
    const int n = mesh_.sides(e);
    Vec2 c(0, 0);
    for (int k = 0; k < n; ++k) c += mesh_.uv[mesh_.corners[e][k]];
    return c / n;
  }

  /// Element distances (breadth-first, through edges) from `target`, up to maxPathLength.
  void distancesFrom(int target) {
    dist_.assign(mesh_.numElements(), kFar);
    std::deque<int> queue{target};
    dist_[target] = 0;
    while (!queue.empty()) {
      const int e = queue.front();
      queue.pop_front();
      if (dist_[e] >= o_.maxPathLength) continue;
      for (int k = 0; k < mesh_.sides(e); ++k) {
        const int f = mesh_.adj[e][k];
        if (f == kNone || dist_[f] != kFar) continue;
        dist_[f] = dist_[e] + 1;
        queue.push_back(f);
      }
    }
  }
  int distance(int e) const { return e == kNone || e >= static_cast<int>(dist_.size()) ? kFar : dist_[e]; }

  /// One step of the walk of triangle `tri` towards `target`: over every quad q next to
  /// tri and every cut of the pentagon tri ∪ q into an ear triangle and a quad (five ears,
  /// the one giving back tri excluded), the legal cut whose triangle is nearest to the
  /// target — by the element distance of its outer neighbours, then by the distance of
  /// its centroid to the target's — if nearer than tri. Returns the moved triangle's id,
  /// or kNone (nothing changed).
  int step(int tri, int target, const Vec2& goal) {
    int bestHops = kFar;
    for (int k = 0; k < 3; ++k) bestHops = std::min(bestHops, distance(mesh_.adj[tri][k]));
    double bestDistance = (centroid(tri) - goal).squaredNorm();
    int bestQuad = kNone;
    std::pair<Corners, Corners> best;
    for (int k = 0; k < 3; ++k) {
      const int q = mesh_.adj[tri][k];
      if (q == kNone || !mesh_.isQuad(q)) continue;
      const Corners& c = mesh_.corners[tri];
      const int u = c[k], v = c[(k + 1) % 3], t3 = c[(k + 2) % 3];
      const int j = mesh_.edgeIndex(q, v, u);
      if (j == kNone) continue;
      const int q2 = mesh_.corners[q][(j + 2) % 4], q3 = mesh_.corners[q][(j + 3) % 4];
      if (t3 == q2 || t3 == q3) continue;
      const std::array<int, 5> p{u, q2, q3, v, t3};
      // The element outside each pentagon edge (p[x], p[x+1]).
      const std::array<int, 5> outside{mesh_.adj[q][(j + 1) % 4], mesh_.adj[q][(j + 2) % 4], mesh_.adj[q][(j + 3) % 4],
                                       mesh_.adj[tri][(k + 1) % 3], mesh_.adj[tri][(k + 2) % 3]};
      auto at = [&](int x) { return p[((x % 5) + 5) % 5]; };
      for (int i = 0; i < 4; ++i) {  // ear at p[4] = t3 would be tri itself
        const int hops = std::min(distance(outside[(i + 4) % 5]), distance(outside[i]));
        const Corners ear{at(i - 1), at(i), at(i + 1), kNone};
        const Corners quad{at(i + 1), at(i + 2), at(i + 3), at(i + 4)};
        const Vec2 mid = (mesh_.uv[ear[0]] + mesh_.uv[ear[1]] + mesh_.uv[ear[2]]) / 3.0;
        const double d = (mid - goal).squaredNorm();
        if (hops > bestHops || (hops == bestHops && d >= bestDistance)) continue;
        if (elementQuality(mesh_, metrics_, ear) <= 0 || elementQuality(mesh_, metrics_, quad) < o_.minQuality) continue;
        bestHops = hops;
        bestDistance = d;
        bestQuad = q;
        best = {ear, quad};
      }
    }
    if (bestQuad == kNone) return kNone;
    const std::array<int, 2> removed{tri, bestQuad};
    const std::array<Corners, 2> added{best.first, best.second};
    const std::array<Corners, 2> old{mesh_.corners[tri], mesh_.corners[bestQuad]};
    const std::vector<int> ids = mesh_.replacePatch(removed, added);
    undo_.push_back({ids, {old[0], old[1]}, {tri, bestQuad}});
    // The new quad keeps the old quad's distance (it covers most of it).
    dist_.resize(mesh_.numElements(), kFar);
    dist_[ids[1]] = distance(bestQuad);
    (void)target;
    return ids[0];
  }

  /// Merges adjacent triangles a and b into a quad when legal.
  bool pair(int a, int b) {
    const int k = sharedEdge(mesh_, a, b);
    if (k == kNone) return false;
    const Corners& c = mesh_.corners[a];
    const int u = c[k], v = c[(k + 1) % 3], x = c[(k + 2) % 3];
    const int i = mesh_.edgeIndex(b, v, u);
    if (i == kNone) return false;
    const Corners quad{u, mesh_.corners[b][(i + 2) % 3], v, x};
    if (elementQuality(mesh_, metrics_, quad) < o_.minQuality) return false;
    const std::array<int, 2> removed{a, b};
    const std::array<Corners, 1> added{quad};
    mesh_.replacePatch(removed, added);
    ++stats_.paired;
    return true;
  }

  /// Walks t towards `target` (step() until they share an edge, at most maxPathLength
  /// steps) and merges the two. On failure every move is undone (the mesh is as before)
  /// and t is set to the restored triangle's new id.
  bool follow(int& t, int target) {
    undo_.clear();
    const Vec2 goal = centroid(target);
    distancesFrom(target);
    int cur = t;
    for (int steps = 0; cur != kNone && sharedEdge(mesh_, cur, target) == kNone; ++steps)
      cur = steps < 4 * o_.maxPathLength ? step(cur, target, goal) : kNone;
    if (cur != kNone && (pair(cur, target) || splitPair(cur, target))) {
      stats_.moves += static_cast<int>(undo_.size());
      return true;
    }
    ++(cur == kNone ? stats_.failedCuts : stats_.failedPairs);
    for (std::size_t i = undo_.size(); i-- > 0;) {
      // Restoring what move i removed gives those elements new ids; earlier moves' undo
      // entries (and t) that name the removed ids must name the new ones.
      const std::vector<int> ids = mesh_.replacePatch(undo_[i].ids, undo_[i].corners);
      for (std::size_t k = 0; k < ids.size(); ++k) {
        for (std::size_t j = 0; j < i; ++j)
          for (int& e : undo_[j].ids)
            if (e == undo_[i].removed[k]) e = ids[k];
        if (t == undo_[i].removed[k]) t = ids[k];
      }
    }
    return false;
  }

  /// The last resort for two adjacent triangles (PairSplit.h).
  bool splitPair(int a, int b) {
    if (!splitPairIntoQuads(mesh_, metrics_, a, b, o_.minQuality)) return false;
    ++stats_.paired;
    ++stats_.splitPairs;
    return true;
  }

  /// After the rounds, each triangle still next to another is split with them and a quad
  /// next to them (HexagonSplit.h): taken only where no partner could be reached otherwise,
  /// since it adds three elements where a pairing adds none.
  void splitLeftPairs() {
    const int n = mesh_.numElements();
    for (int t = 0; t < n; ++t)
      for (int k = 0; k < 3 && mesh_.isTriangle(t); ++k) {
        const int u = mesh_.adj[t][k];
        if (u == kNone || !mesh_.isTriangle(u) || !splitPairWithQuad(mesh_, metrics_, t, u, o_.minQuality)) continue;
        ++stats_.paired;
        ++stats_.hexagonSplits;
      }
  }

  TransportStats run() {
    for (int round = 0; round < o_.rounds; ++round) {
      std::vector<int> tris;
      for (int e = 0; e < mesh_.numElements(); ++e)
        if (mesh_.isTriangle(e)) tris.push_back(e);
      const int before = stats_.paired;
      for (int t : tris) {
        for (int attempt = 0; attempt < o_.partners && mesh_.isTriangle(t); ++attempt) {
          const auto paths = pathsToTriangles(mesh_, t, o_.maxPathLength, attempt + 1);
          if (static_cast<int>(paths.size()) <= attempt) break;
          // The chain re-quadrangulated, else t walks to the partner, else the partner to t.
          if (quadrangulateChain(mesh_, metrics_, paths[attempt], {o_.minQuality})) {
            ++stats_.paired;
            ++stats_.chains;
            break;
          }
          int partner = paths[attempt].back();
          if (follow(t, partner) || follow(partner, t)) break;
        }
      }
      if (stats_.paired == before) break;
    }
    splitLeftPairs();
    for (int e = 0; e < mesh_.numElements(); ++e) stats_.triangles += mesh_.isTriangle(e);
    return stats_;
  }

 private:
  QuadMesh2d& mesh_;
  VertexMetrics& metrics_;
  const TransportOptions& o_;
  TransportStats stats_;
  struct Undo {
    std::vector<int> ids;          ///< the elements the move created
    std::vector<Corners> corners;  ///< the elements it removed
    std::vector<int> removed;      ///< their ids
  };
  std::vector<Undo> undo_;
  static constexpr int kFar = 1 << 30;
  std::vector<int> dist_;
};

}  // namespace

TransportStats pairTriangles(QuadMesh2d& mesh, VertexMetrics& metrics, const TransportOptions& options) {
  return Transport(mesh, metrics, options).run();
}

}  // namespace aniso::quad
