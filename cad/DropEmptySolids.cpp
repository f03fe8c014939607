// Solids that hold no face (a SOLID with no shell, or only empty shells) are taken out of
// the shape as read: nothing of them can be meshed, and OCCT's fuse treats them as
// infinite (Axis_of_bearing.brep of OCCT's samples: solid 15 of 18, empty).
#include <BRepTools_ReShape.hxx>
#include <TopExp.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "cad/detail/Readers.h"

namespace aniso::cad::detail {

int dropEmptySolids(CadModel::Impl& impl) {
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(impl.shape, TopAbs_SOLID, solids);
  std::vector<int> empty;
  for (int i = 1; i <= solids.Extent(); ++i) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solids(i), TopAbs_FACE, faces);
    if (faces.IsEmpty()) empty.push_back(i);
  }
  if (empty.empty()) return 0;
  // the solids keep the names they had by their place in the file ("SOLID<id>" when the
  // file names none), so that the ids a user reads in the report do not shift
  for (int i = 1; i <= solids.Extent(); ++i) {
    const TopoDS_Shape key = solids(i).Located(TopLoc_Location());
    if (impl.nameIndex.IsBound(key) && !impl.names[static_cast<size_t>(impl.nameIndex.Find(key))].empty()) continue;
    impl.names.push_back(impl.solidName(solids(i), i));
    impl.partColors.resize(impl.names.size());
    if (impl.nameIndex.IsBound(key))
      impl.nameIndex.ChangeFind(key) = static_cast<int>(impl.names.size()) - 1;
    else
      impl.nameIndex.Bind(key, static_cast<int>(impl.names.size()) - 1);
  }
  Handle(BRepTools_ReShape) reshape = new BRepTools_ReShape;
  std::string ids;
  for (const int i : empty) {
    reshape->Remove(solids(i));
    ids += (ids.empty() ? "" : ", ") + std::to_string(i) + " \"" + impl.solidName(solids(i), i) + "\"";
  }
  impl.shape = reshape->Apply(impl.shape);
  impl.solidsLost += static_cast<int>(empty.size());
  impl.readWarnings.push_back("solid(s) " + ids + " hold no face (no shell): left out, nothing of them can be meshed");
  return static_cast<int>(empty.size());
}

}  // namespace aniso::cad::detail
