#include "mesher/quad/RegionParity.h"

#include <algorithm>
#include <array>
#include <deque>

namespace aniso::quad {

int RegionParity::find(int g) {
  while (parent_[g] != g) g = parent_[g] = parent_[parent_[g]];
  return g;
}

bool RegionParity::mergeKeepsParity(const QuadMesh2d& mesh, int t1, int t2, int maxVisits) {
  const std::array<int, 2> pair{t1, t2};
  return removalKeepsParity(mesh, pair, maxVisits);
}

bool RegionParity::removalKeepsParity(const QuadMesh2d& mesh, std::span<const int> removed, int maxVisits) {
  if (static_cast<int>(mark_.size()) < mesh.numElements()) {
    mark_.resize(mesh.numElements(), 0);
    label_.resize(mesh.numElements(), 0);
  }
  ++epoch_;
  for (int t : removed) {
    mark_[t] = epoch_;
    label_[t] = -1;
  }
  // Seeds: the region triangles across the pair's outer edges, one group each.
  std::vector<std::deque<int>> queue;
  std::vector<long long> count;
  parent_.clear();
  for (int t : removed)
    for (int k = 0; k < 3; ++k) {
      const int g = mesh.adj[t][k];
      if (g == kNone || !mesh.isTriangle(g) || mark_[g] == epoch_) continue;
      mark_[g] = epoch_;
      label_[g] = static_cast<int>(queue.size());
      parent_.push_back(static_cast<int>(queue.size()));
      queue.push_back({g});
      count.push_back(1);
    }
  const int groups = static_cast<int>(queue.size());
  if (groups <= 1) return true;
  int visits = 0;
  while (true) {
    int growing = 0;
    std::vector<int> roots;
    for (int g = 0; g < groups; ++g) {
      if (queue[g].empty()) continue;
      const int r = find(g);
      if (std::find(roots.begin(), roots.end(), r) == roots.end()) roots.push_back(r);
    }
    growing = static_cast<int>(roots.size());
    if (growing <= 1 && groups > 0) {
      // Every root other than the growing one is a finished piece.
      std::vector<int> finished;
      for (int g = 0; g < groups; ++g) {
        const int r = find(g);
        if ((growing == 0 || r != roots[0]) && std::find(finished.begin(), finished.end(), r) == finished.end())
          finished.push_back(r);
      }
      int odd = 0;
      long long total = 0;
      for (int r : finished) {
        odd += static_cast<int>(count[r] % 2);
        total += count[r];
      }
      if (growing == 1) return odd == 0;
      return odd == 0 || (odd == 1 && total % 2 == 1);
    }
    for (int g = 0; g < groups; ++g) {
      if (queue[g].empty()) continue;
      const int t = queue[g].front();
      queue[g].pop_front();
      if (++visits > maxVisits) return true;
      for (int k = 0; k < 3; ++k) {
        const int u = mesh.adj[t][k];
        if (u == kNone || !mesh.isTriangle(u)) continue;
        if (mark_[u] == epoch_) {
          if (label_[u] < 0) continue;  // a removed triangle
          const int a = find(g), b = find(label_[u]);
          if (a != b) {
            parent_[b] = a;
            count[a] += count[b];
          }
          continue;
        }
        mark_[u] = epoch_;
        label_[u] = g;
        ++count[find(g)];
        queue[g].push_back(u);
      }
    }
  }
}

}  // namespace aniso::quad
