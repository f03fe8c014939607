#include <BRepClass3d.hxx>
#include <BRep_Builder.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_DataMapOfShapeShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>

#include "cad/detail/Prepare.h"
#include "cad/detail/SheetShell.h"

namespace aniso::cad::detail {

InternalFaces collectInternalFaces(const TopoDS_Shape& shape) {
  InternalFaces out;
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  for (int i = 1; i <= solids.Extent(); ++i) {
    TopTools_ListOfShape faces;
    for (TopExp_Explorer f(solids(i), TopAbs_FACE); f.More(); f.Next())
      if (f.Current().Orientation() == TopAbs_INTERNAL) faces.Append(f.Current());
    // the faces of a sheet stored as a void shell (SheetShell.h): inside the material too;
    // a solid of one shell has none to classify
    int shells = 0;
    for (TopoDS_Iterator s(solids(i)); s.More(); s.Next()) shells += s.Value().ShapeType() == TopAbs_SHELL;
    const TopoDS_Shape outer = shells > 1 ? BRepClass3d::OuterShell(TopoDS::Solid(solids(i))) : TopoDS_Shape();
    for (TopoDS_Iterator s(solids(i)); s.More() && shells > 1; s.Next())
      if (s.Value().ShapeType() == TopAbs_SHELL && !s.Value().IsSame(outer) && isSheetShell(s.Value()))
        for (TopExp_Explorer f(s.Value(), TopAbs_FACE); f.More(); f.Next())
          if (f.Current().Orientation() != TopAbs_INTERNAL && f.Current().Orientation() != TopAbs_EXTERNAL)
            faces.Append(f.Current());
    if (!faces.IsEmpty()) out.push_back({solids(i), i, solids.Extent(), faces});
  }
  return out;
}

int restoreInternalFaces(CadModel::Impl& impl, const InternalFaces& kept, const Handle(ShapeBuild_ReShape)& context) {
  TopTools_IndexedMapOfShape solids;
  TopExp::MapShapes(impl.shape, TopAbs_SOLID, solids);
  TopTools_DataMapOfShapeShape replaced;  // fixed solid -> the same with its internal faces again
  BRep_Builder b;
  for (const InternalFacesOf& k : kept) {
    // The solid's image: through the fixer's context, else the one at the same place when
    // the fixer kept the number of solids (it rebuilds some without recording them).
    TopTools_IndexedMapOfShape images;
    TopExp::MapShapes(context->Apply(k.solid), TopAbs_SOLID, images);
    TopoDS_Shape image;
    if (images.Extent() == 1 && solids.Contains(images(1))) image = images(1);
    else if (solids.Extent() == k.count) image = solids(k.index);
    else continue;
    TopTools_IndexedMapOfShape imageFaces;
    TopExp::MapShapes(image, TopAbs_FACE, imageFaces);
    bool kept = false;  // the fixer left them in the solid
    for (const TopoDS_Shape& f : k.faces) kept = kept || imageFaces.Contains(context->Apply(f));
    if (kept) continue;
    // The image's shells (placed as in the shape), then one shell of the internal faces,
    // their edges renamed as the fixer renamed them in the solid's other faces.
    TopoDS_Solid rebuilt;
    b.MakeSolid(rebuilt);
    for (TopoDS_Iterator s(image); s.More(); s.Next()) b.Add(rebuilt, s.Value());
    TopoDS_Shell shell;
    b.MakeShell(shell);
    for (const TopoDS_Shape& f : k.faces) b.Add(shell, context->Apply(f).Oriented(TopAbs_INTERNAL));
    b.Add(rebuilt, shell);
    const TopoDS_Shape key = image.Located(TopLoc_Location());
    if (impl.nameIndex.IsBound(key)) impl.nameIndex.Bind(rebuilt, impl.nameIndex.Find(key));
    replaced.Bind(image, rebuilt);
  }
  if (replaced.IsEmpty()) return 0;
  TopoDS_Compound c;
  b.MakeCompound(c);
  TopTools_IndexedMapOfShape now;  // the solids as they will be: an internal face is not loose
  for (int i = 1; i <= solids.Extent(); ++i) {
    now.Add(replaced.IsBound(solids(i)) ? replaced.Find(solids(i)) : solids(i));
    b.Add(c, now(i));
  }
  addLooseFaces(impl.shape, now, c);
  impl.shape = c;
  return replaced.Extent();
}

}  // namespace aniso::cad::detail
