#include "mesher/sizing/SurfaceBudget.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesher/core/ParallelFor.h"

namespace aniso {

ElementBudget surfaceBudget(const Model& model, const std::vector<std::unique_ptr<CSQuadtree2d>>& spaces,
                            const std::vector<FaceBoundary>& boundaries, const MeshOptions& options) {
  const int nf = static_cast<int>(spaces.size());
  std::vector<FaceSizePrediction> predictions(nf);
  parallelFor(nf, options.threads, [&](int f) {
    if (spaces[f]) predictions[f] = FaceSizePrediction(*spaces[f], boundaries[f]);
  }, "element budget");
  std::vector<const FaceSizePrediction*> faces(nf, nullptr);
  for (int f = 0; f < nf; ++f)
    if (spaces[f]) faces[f] = &predictions[f];
  std::vector<std::vector<int>> solidFaces;
  const bool volume = options.dim == 3 || (options.dim == 0 && !model.solids.empty());
  if (volume)
    for (const ModelSolid& s : model.solids) {
      std::vector<int>& list = solidFaces.emplace_back();
      std::vector<int> shells = s.voidShells;
      shells.push_back(s.outerShell);
      for (int sh : shells)
        if (sh >= 0)
          for (const FaceUse& u : model.shells.at(static_cast<std::size_t>(sh)).faces) list.push_back(u.face);
    }
  return decideBudget(faces, solidFaces, options.maxElements, options.sizing.hmaxFor(model.diagonal()));
}

bool applyBudgetFloor(const ElementBudget& budget, std::vector<std::unique_ptr<CSQuadtree2d>>& spaces) {
  if (!(budget.floor > 0)) return false;
  int changed = 0;
  for (auto& cs : spaces)
    if (cs) changed += applySizeFloor(*cs, budget.floor);
  return changed > 0;
}

std::string budgetRefusal(const ElementBudget& b) {
  const auto count = [](double x) { return std::to_string(static_cast<long long>(std::llround(std::min(x, 1e18)))); };
  std::string text = "the sizing asks for about " + count(b.predicted) + " elements (" + count(b.triangles) + " triangles";
  if (b.tets > 0) text += ", " + count(b.tets) + " tets";
  return text + "), and even the largest size (h_max) everywhere would make more than the element budget of " +
         count(b.limit) + " (--max-elements): raise the budget or the sizes (--hmax-rel, --curvature-ratio)";
}

}  // namespace aniso
