#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "cad/detail/FaceTags.h"

namespace aniso::cad::detail {

void carryFaceTags(CadModel::Impl& impl, const TopoDS_Shape& before, const FaceImages& images) {
  if (impl.faceTagIndex.IsEmpty()) return;
  TopTools_IndexedMapOfShape oldFaces;
  TopExp::MapShapes(before, TopAbs_FACE, oldFaces);
  for (int i = 1; i <= oldFaces.Extent(); ++i) {
    const TopoDS_Shape key = oldFaces(i).Located(TopLoc_Location());
    if (!impl.faceTagIndex.IsBound(key)) continue;
    const int tag = impl.faceTagIndex.Find(key);
    TopTools_IndexedMapOfShape faces;
    try {
      for (const TopoDS_Shape& image : images(oldFaces(i))) TopExp::MapShapes(image, TopAbs_FACE, faces);
    } catch (const Standard_Failure&) {
      continue;  // the history cannot say: the face loses its tag
    }
    for (int k = 1; k <= faces.Extent(); ++k) {
      const TopoDS_Shape imageKey = faces(k).Located(TopLoc_Location());
      if (!impl.faceTagIndex.IsBound(imageKey)) impl.faceTagIndex.Bind(imageKey, tag);
    }
  }
}

void dropStaleFaceTags(CadModel::Impl& impl) {
  if (impl.faceTagIndex.IsEmpty()) return;
  TopTools_IndexedMapOfShape nowFaces;
  TopExp::MapShapes(impl.shape, TopAbs_FACE, nowFaces);
  TopTools_IndexedMapOfShape nowKeys;
  for (int i = 1; i <= nowFaces.Extent(); ++i) nowKeys.Add(nowFaces(i).Located(TopLoc_Location()));
  TopTools_DataMapOfShapeInteger kept;
  for (TopTools_DataMapIteratorOfDataMapOfShapeInteger it(impl.faceTagIndex); it.More(); it.Next())
    if (nowKeys.Contains(it.Key())) kept.Bind(it.Key(), it.Value());
  impl.faceTagIndex = kept;
}

TopTools_ListOfShape imageList(const TopoDS_Shape& s) {
  TopTools_ListOfShape out;
  if (!s.IsNull()) out.Append(s);
  return out;
}

TopTools_ListOfShape historyImages(const Handle(BRepTools_History)& history, const TopoDS_Shape& face) {
  TopTools_ListOfShape out;
  if (history.IsNull()) {
    out.Append(face);
    return out;
  }
  if (history->IsRemoved(face)) return out;
  const TopTools_ListOfShape& modified = history->Modified(face);
  if (modified.IsEmpty()) out.Append(face);
  else out = modified;
  return out;
}

}  // namespace aniso::cad::detail
