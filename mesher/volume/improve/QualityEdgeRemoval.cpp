#include "mesher/volume/improve/QualityEdgeRemoval.h"

#include <algorithm>

#include "mesher/delaunay3d/LocalRetriangulation.h"
#include "mesher/volume/EdgeRemoval.h"

namespace aniso::improve3d {

bool removeEdgeByQuality(SolidTetMesh& s, const VertexMetrics& vm, del3d::TetId t, int i, int j,
                         std::vector<del3d::TetId>& created) {
  const int n = volume::removalRingSize(s.mesh, t, i, j);
  if (n < 3) return false;
  volume::LocalPlan best, plan;
  double bestScore = -1e300;
  for (int fan = 0; fan < n; ++fan) {
    if (!volume::canRemoveEdge(s.mesh, t, i, j, fan, &plan)) continue;
    double worst = 1e300;
    for (const auto& q : plan.newTets) worst = std::min(worst, vm.score(q));
    if (worst > bestScore) bestScore = worst, best = std::move(plan);
  }
  if (best.newTets.empty()) return false;
  double before = 1e300;
  for (const del3d::TetId u : best.oldTets) before = std::min(before, vm.score(u));
  if (!(bestScore > before)) return false;
  std::vector<del3d::TetId> ids(best.newTets.size());
  del3d::replaceTets(s.mesh, best.oldTets, best.newTets, ids);
  created.insert(created.end(), ids.begin(), ids.end());
  return true;
}

}  // namespace aniso::improve3d
