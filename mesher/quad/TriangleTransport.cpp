#include "mesher/quad/TriangleTransport.h"

#include <algorithm>
#include <array>
#include <deque>

namespace aniso::quad {
namespace {

/// Shortest paths of elements (by adjacency) from triangle t to the nearest other live
/// triangles (up to maxTargets of them, nearest first), both ends included.
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

  /// Moves triangle `tri` across quad q so that it ends next to `next`. Returns the moved
  /// triangle's id, or kNone when no legal cut exists (nothing changed).
  int cross(int tri, int q, int next) {
    const int k = sharedEdge(mesh_, tri, q);
    if (k == kNone) return kNone;
    const Corners& c = mesh_.corners[tri];
    const int u = c[k], v = c[(k + 1) % 3], t3 = c[(k + 2) % 3];
    const int j = mesh_.edgeIndex(q, v, u);
    if (j == kNone) return kNone;
    const int q2 = mesh_.corners[q][(j + 2) % 4], q3 = mesh_.corners[q][(j + 3) % 4];
    if (t3 == q2 || t3 == q3) return kNone;
    const std::array<int, 5> p{u, q2, q3, v, t3};
    const int m = sharedEdge(mesh_, q, next);
    if (m == kNone) return kNone;
    const int s = mesh_.corners[q][m], t = mesh_.corners[q][(m + 1) % 4];
    int i = kNone;
    for (int x = 0; x < 5; ++x)
      if (p[x] == s && p[(x + 1) % 5] == t) i = x;
    if (i == kNone) return kNone;
    auto at = [&](int x) { return p[((x % 5) + 5) % 5]; };
    const std::array<std::pair<Corners, Corners>, 2> cuts{
        std::pair<Corners, Corners>{{at(i - 1), at(i), at(i + 1), kNone}, {at(i + 1), at(i + 2), at(i + 3), at(i + 4)}},
        std::pair<Corners, Corners>{{at(i), at(i + 1), at(i + 2), kNone}, {at(i + 2), at(i + 3), at(i + 4), at(i)}}};
    double best = o_.minQuality;
    int choice = kNone;
    for (int x = 0; x < 2; ++x) {
      const double qq = elementQuality(mesh_, metrics_, cuts[x].second);
      if (qq >= best && elementQuality(mesh_, metrics_, cuts[x].first) > 0) {
        best = qq;
        choice = x;
      }
    }
    if (choice == kNone) return kNone;
    const std::array<int, 2> removed{tri, q};
    const std::array<Corners, 2> added{cuts[choice].first, cuts[choice].second};
    const std::array<Corners, 2> old{mesh_.corners[tri], mesh_.corners[q]};
    const std::vector<int> ids = mesh_.replacePatch(removed, added);
    undo_.push_back({ids, {old[0], old[1]}});
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

  /// Moves t along path and merges it with the path's last triangle. On failure every move
  /// is undone (the mesh is as before) and t is set to the restored triangle's new id.
  bool follow(int& t, const std::vector<int>& path) {
    undo_.clear();
    int cur = t;
    for (std::size_t i = 1; i + 1 < path.size(); ++i) {
      cur = cross(cur, path[i], path[i + 1]);
      if (cur == kNone) break;
    }
    if (cur != kNone && pair(cur, path.back())) {
      stats_.moves += static_cast<int>(undo_.size());
      return true;
    }
    for (std::size_t i = undo_.size(); i-- > 0;) {
      // Move i removed (the triangle = move i−1's first new element, a quad): restoring it
      // gives that triangle a new id, which move i−1's undo must remove.
      const std::vector<int> ids = mesh_.replacePatch(undo_[i].ids, undo_[i].corners);
      if (i > 0) undo_[i - 1].ids[0] = ids[0];
      else t = ids[0];
    }
    return false;
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
          if (static_cast<int>(paths.size()) <= attempt || follow(t, paths[attempt])) break;
        }
      }
      if (stats_.paired == before) break;
    }
    for (int e = 0; e < mesh_.numElements(); ++e) stats_.triangles += mesh_.isTriangle(e);
    return stats_;
  }

 private:
  QuadMesh2d& mesh_;
  VertexMetrics& metrics_;
  const TransportOptions& o_;
  TransportStats stats_;
  struct Undo {
    std::vector<int> ids;
    std::vector<Corners> corners;
  };
  std::vector<Undo> undo_;
};

}  // namespace

TransportStats pairTriangles(QuadMesh2d& mesh, VertexMetrics& metrics, const TransportOptions& options) {
  return Transport(mesh, metrics, options).run();
}

}  // namespace aniso::quad
