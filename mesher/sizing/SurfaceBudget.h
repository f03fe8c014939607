#pragma once
// The element budget of a whole surface meshing run (ElementBudget.h) on its face control
// spaces, after the contours are discretized and before any face is meshed (SurfaceMesher
// step 2b).
#include <memory>
#include <string>
#include <vector>

#include "mesher/control/CSQuadtree2d.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/model/Model.h"
#include "mesher/sizing/ElementBudget.h"
#include "mesher/surface/FaceBoundary.h"

namespace aniso {

/// The prediction for `options.maxElements` (≤ 0: no limit, the prediction only): the faces
/// with a control space (null: not meshed) bounded by their boundaries; tets too when the
/// run makes a volume mesh (dim 3, or dim 0 with solids). Faces in parallel on
/// options.threads threads.
ElementBudget surfaceBudget(const Model& model, const std::vector<std::unique_ptr<CSQuadtree2d>>& spaces,
                            const std::vector<FaceBoundary>& boundaries, const MeshOptions& options);

/// Applies the budget's floor (if any) to every control space; returns whether any changed.
bool applyBudgetFloor(const ElementBudget& budget, std::vector<std::unique_ptr<CSQuadtree2d>>& spaces);

/// The sentence of a run that cannot fit: the prediction (triangles, tets) and the limit.
std::string budgetRefusal(const ElementBudget& budget);
/// The one warning line of a coarsened run: the prediction, the limit, the coarsened faces
/// (1-based, the first maxNamed of them), the floor and the new prediction; empty when
/// nothing was coarsened.
std::string budgetWarning(const ElementBudget& budget, std::size_t maxNamed = 10);

}  // namespace aniso
