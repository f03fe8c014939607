#include "mesher/pipeline/UndoRefinement.h"

#include <algorithm>

#include "mesher/volume/CoarseSolids.h"

namespace aniso {

std::size_t undoRefinementOfFailed(const Model& model, std::size_t userSources, const std::vector<SolidOutcome>& solids,
                                   UserSizing& sizing, ProximityOutcome& px) {
  std::vector<int> faces;
  for (const int s : failedSolids(solids)) {
    if (s >= static_cast<int>(model.solids.size())) continue;
    const std::vector<int> f = model.solidBoundaryFaces(s);
    faces.insert(faces.end(), f.begin(), f.end());
  }
  std::sort(faces.begin(), faces.end());
  const auto failedFace = [&](int f) { return std::binary_search(faces.begin(), faces.end(), f); };
  const auto ofFailed = [&](const SizingSource& s) {
    return !s.faces.empty() && std::all_of(s.faces.begin(), s.faces.end(), failedFace);
  };
  const std::size_t first = std::min(userSources, sizing.sources.size());
  const auto kept = std::stable_partition(sizing.sources.begin() + static_cast<std::ptrdiff_t>(first),
                                          sizing.sources.end(), [&](const SizingSource& s) { return !ofFailed(s); });
  const auto undone = static_cast<std::size_t>(sizing.sources.end() - kept);
  sizing.sources.erase(kept, sizing.sources.end());
  px.refined.erase(std::remove_if(px.refined.begin(), px.refined.end(), [&](const auto& fh) { return failedFace(fh.first); }),
                   px.refined.end());
  px.facesRefined = px.refined.size();
  return undone;
}

}  // namespace aniso
