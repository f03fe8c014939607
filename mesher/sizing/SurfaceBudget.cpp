#include "mesher/sizing/SurfaceBudget.h"

#include <algorithm>
#include <cstdio>
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
  std::vector<double> solidVolumes;
  const bool volume = options.dim == 3 || (options.dim == 0 && !model.solids.empty());
  if (volume)
    for (std::size_t s = 0; s < model.solids.size(); ++s) {
      solidFaces.push_back(model.solidFaces(static_cast<int>(s)));
      solidVolumes.push_back(model.solids[s].cadVolume);
    }
  return decideBudget(faces, solidFaces, options.maxElements, options.sizing.hmaxFor(model.diagonal()), solidVolumes);
}

bool applyBudgetFloor(const ElementBudget& budget, std::vector<std::unique_ptr<CSQuadtree2d>>& spaces) {
  if (!(budget.floor > 0)) return false;
  int changed = 0;
  for (auto& cs : spaces)
    if (cs) changed += applySizeFloor(*cs, budget.floor);
  return changed > 0;
}

namespace {

std::string count(double x) { return std::to_string(static_cast<long long>(std::llround(std::min(x, 1e18)))); }

std::string g3(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

}  // namespace

std::string budgetRefusal(const ElementBudget& b) {
  std::string text = "the sizing asks for about " + count(b.predicted) + " elements (" + count(b.triangles) + " triangles";
  if (b.tets > 0) text += ", " + count(b.tets) + " tets";
  return text + "), and even the largest size (h_max) everywhere would make more than the element budget of " +
         count(b.limit) + " (--max-elements): raise the budget or the sizes (--hmax-rel, --curvature-ratio)";
}

std::string budgetWarning(const ElementBudget& b, std::size_t maxNamed) {
  if (b.coarsened.empty()) return {};
  std::string names;
  const std::size_t shown = std::min(b.coarsened.size(), std::max<std::size_t>(maxNamed, 1));
  for (std::size_t i = 0; i < shown; ++i) names += (i ? ", " : "") + std::to_string(b.coarsened[i].face + 1);
  if (shown < b.coarsened.size()) names += " and " + std::to_string(b.coarsened.size() - shown) + " more";
  return "the sizing asks for " + count(b.predicted) + " elements, over the budget of " + count(b.limit) +
         " (--max-elements): face" + (b.coarsened.size() > 1 ? "s " : " ") + names +
         " coarsened to sizes of at least " + g3(b.floor) + " (" + count(b.predictedAfter) + " elements predicted)";
}

}  // namespace aniso
