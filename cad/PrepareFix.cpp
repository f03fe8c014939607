#include <ShapeBuild_ReShape.hxx>
#include <ShapeFix_Shape.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include "cad/detail/FaceTags.h"
#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {

void fixShape(CadModel::Impl& impl, double diag, PrepareReport& report) {
  try {
    const InternalFaces internal = collectInternalFaces(impl.shape);
    Handle(ShapeFix_Shape) fixer = new ShapeFix_Shape(impl.shape);
    // Fixes may not open gaps larger than a small fraction of the model.
    fixer->SetMaxTolerance(1e-3 * diag);
    if (const int split = splitLoopsOfClosedEdges(impl.shape, *fixer->Context()))
      report.warnings.push_back(std::to_string(split) +
                                " face(s) had a boundary loop made of separate closed edges (no seam joining "
                                "them): split into one loop per edge");
    fixer->Perform();
    const TopoDS_Shape fixed = fixer->Shape();
    if (fixed.IsNull()) {
      report.warnings.push_back("shape fixing produced nothing; the shape is kept as read");
      return;
    }
    // Carry the part names over to the fixed solids.
    TopTools_IndexedMapOfShape solids;
    TopExp::MapShapes(impl.shape, TopAbs_SOLID, solids);
    for (int i = 1; i <= solids.Extent(); ++i) {
      const TopoDS_Shape key = solids(i).Located(TopLoc_Location());
      if (!impl.nameIndex.IsBound(key)) continue;
      const int name = impl.nameIndex.Find(key);
      TopTools_IndexedMapOfShape images;
      TopExp::MapShapes(fixer->Context()->Value(solids(i)), TopAbs_SOLID, images);
      for (int k = 1; k <= images.Extent(); ++k) {
        const TopoDS_Shape ik = images(k).Located(TopLoc_Location());
        if (!impl.nameIndex.IsBound(ik)) impl.nameIndex.Bind(ik, name);
      }
    }
    // A solid the fixer rebuilt without recording it at the solid level (only its faces
    // are in the context) keeps its place: with as many solids as before, the i-th fixed
    // solid still unnamed takes the i-th original's name.
    TopTools_IndexedMapOfShape fixedSolids;
    TopExp::MapShapes(fixed, TopAbs_SOLID, fixedSolids);
    if (fixedSolids.Extent() == solids.Extent())
      for (int i = 1; i <= solids.Extent(); ++i) {
        const TopoDS_Shape key = solids(i).Located(TopLoc_Location());
        const TopoDS_Shape fk = fixedSolids(i).Located(TopLoc_Location());
        if (impl.nameIndex.IsBound(key) && !impl.nameIndex.IsBound(fk)) impl.nameIndex.Bind(fk, impl.nameIndex.Find(key));
      }
    const TopoDS_Shape before = impl.shape;
    impl.shape = fixed;
    restoreInternalFaces(impl, internal, fixer->Context());
    const Handle(ShapeBuild_ReShape) context = fixer->Context();
    carryFaceTags(impl, before, [&context](const TopoDS_Shape& f) { return imageList(context->Apply(f)); });
    dropStaleFaceTags(impl);
    rebuildSelfIntersecting(impl, report);
  } catch (const Standard_Failure& e) {
    report.warnings.push_back(std::string("shape fixing failed (") + e.GetMessageString() +
                              "); the shape is kept as read");
  }
}

}  // namespace aniso::cad::detail
