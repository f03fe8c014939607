// The fuse's result checked by the mesher's own rule (cad/detail/Prepare.h, flawedFaceCounts).
#include <Standard_Failure.hxx>
#include <TopExp.hxx>

#include "cad/TopologyBuilder.h"
#include "cad/detail/Prepare.h"
#include "mesher/core/Error.h"

namespace aniso::cad::detail {

std::vector<int> flawedFaceCounts(const TopoDS_Shape& whole, const std::vector<TopTools_IndexedMapOfShape>& parts) {
  std::vector<int> count(parts.size(), 0);
  TopTools_IndexedMapOfShape faces;
  std::vector<char> flawed;
  try {
    TopExp::MapShapes(whole, TopAbs_FACE, faces);
    // the check reads faces only: no solid volumes (an adaptive integral per solid per fuse)
    const Model model = buildTopology(whole, [](const TopoDS_Shape&, int) { return std::string(); },
                                      [](const TopoDS_Shape&) { return 0.0; });
    flawed.assign(model.faces.size(), 0);
    for (const ModelIssue& issue : model.check())
      if (issue.kind == EntityKind::Face && issue.index >= 0 && static_cast<std::size_t>(issue.index) < flawed.size() &&
          (issue.level != ModelIssue::Level::Defect || issue.uvGapShare > kFuseLoopGapShare))
        flawed[static_cast<std::size_t>(issue.index)] = 1;
    const double diag = model.diagonal();
    for (std::size_t f = 0; f < model.faces.size(); ++f)
      if (model.faces[f].cadArea <= kNoAreaRel * diag * diag) flawed[f] = 1;
  } catch (const MeshingError&) {
    flawed.clear();
  } catch (const Standard_Failure&) {
    flawed.clear();
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    TopTools_IndexedMapOfShape own;
    for (int k = 1; k <= parts[i].Extent(); ++k) TopExp::MapShapes(parts[i](k), TopAbs_FACE, own);
    if (flawed.empty()) {  // the mesher could not read the result at all
      count[i] = own.Extent() > 0 ? own.Extent() : 1;
      continue;
    }
    for (int k = 1; k <= own.Extent(); ++k) {
      const int id = faces.FindIndex(own(k));
      if (id > 0 && static_cast<std::size_t>(id) <= flawed.size() && flawed[static_cast<std::size_t>(id) - 1]) ++count[i];
    }
  }
  return count;
}

}  // namespace aniso::cad::detail
