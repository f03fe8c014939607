#include "tools/app/SelfIntersections.h"

#include <algorithm>

namespace aniso::app {

std::vector<int> selfCrossingSolids(const MeshResult& result) {
  std::vector<int> out;
  for (std::size_t s = 0; s < result.volume.solids.size(); ++s) {
    const std::vector<Problem>& ps = result.volume.solids[s].problems;
    if (std::any_of(ps.begin(), ps.end(), [](const Problem& p) { return p.code == "boundary-self-crossing"; }))
      out.push_back(static_cast<int>(s) + 1);
  }
  return out;
}

bool rebuildSelfIntersecting(ModelInput& in, const std::string& file, const std::vector<int>& solids) {
  if (!in.cad || solids.empty()) return false;
  const cad::PrepareReport before = in.prepared;
  in.prepareOptions.checkSelfIntersections.clear();
  for (const int id : solids)  // as numbered after shape fixing
    in.prepareOptions.checkSelfIntersections.push_back(
        id >= 1 && static_cast<std::size_t>(id) <= before.solidOrigin.size()
            ? before.solidOrigin[static_cast<std::size_t>(id - 1)]
            : id);
  prepareModel(in, file, before.warnings, "prepare again", "topology again");
  return !in.prepared.rebuiltSolids.empty();
}

}  // namespace aniso::app
