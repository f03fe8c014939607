#include "mesher/model/ChainLoop.h"

#include <utility>

namespace aniso {

void chainLoopUses(const Model& model, std::vector<EdgeUse>& uses) {
  const auto uvAt = [&model](const EdgeUse& u, bool end) {
    const ModelEdge& e = model.edges[static_cast<std::size_t>(u.edge)];
    const PCurve& pc = e.pcurves[static_cast<std::size_t>(u.pcurve)];
    return pc.curve->point(end != u.reversed ? pc.t1 : pc.t0);
  };
  const auto vertexAt = [&model](const EdgeUse& u, bool end) {
    const ModelEdge& e = model.edges[static_cast<std::size_t>(u.edge)];
    return end != u.reversed ? e.v1 : e.v0;
  };
  std::vector<EdgeUse> ordered{uses.front()};
  std::vector<char> taken(uses.size(), 0);
  taken[0] = 1;
  while (ordered.size() < uses.size()) {
    const int v = vertexAt(ordered.back(), true);
    const Vec2 at = uvAt(ordered.back(), true);
    std::size_t best = uses.size();
    double bestDistance = 0;
    for (std::size_t j = 0; j < uses.size(); ++j) {
      if (taken[j] || vertexAt(uses[j], false) != v) continue;
      const double d = (uvAt(uses[j], false) - at).norm();
      if (best == uses.size() || d < bestDistance) {
        best = j;
        bestDistance = d;
      }
    }
    if (best == uses.size()) return;  // no chain: the stored order stays
    taken[best] = 1;
    ordered.push_back(uses[best]);
  }
  uses = std::move(ordered);
}

}  // namespace aniso
