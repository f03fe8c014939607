#include <BRepBuilderAPI_Sewing.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include "cad/detail/FaceTags.h"
#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {

int countFreeEdges(const TopoDS_Shape& shape) {
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  int n = 0;
  for (int i = 1; i <= edgeFaces.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edgeFaces.FindKey(i));
    if (BRep_Tool::Degenerated(e)) continue;
    TopTools_IndexedMapOfShape distinct;
    for (const TopoDS_Shape& f : edgeFaces(i)) distinct.Add(f);
    // A seam is used twice by one face: it is not free.
    if (distinct.Extent() == 1 && !BRep_Tool::IsClosed(e, TopoDS::Face(distinct(1)))) ++n;
  }
  return n;
}

void sewLooseFaces(CadModel::Impl& impl, double tol, PrepareReport& report) {
  // Split the shape into solids (kept as they are) and the faces outside any solid.
  TopTools_IndexedMapOfShape inSolid;
  for (TopExp_Explorer s(impl.shape, TopAbs_SOLID); s.More(); s.Next())
    TopExp::MapShapes(s.Current(), TopAbs_FACE, inSolid);
  BRep_Builder b;
  TopoDS_Compound loose, solids;
  b.MakeCompound(loose);
  b.MakeCompound(solids);
  int nLoose = 0;
  TopTools_IndexedMapOfShape seen;
  for (TopExp_Explorer f(impl.shape, TopAbs_FACE); f.More(); f.Next()) {
    if (inSolid.Contains(f.Current()) || seen.Contains(f.Current())) continue;
    seen.Add(f.Current());
    b.Add(loose, f.Current());
    ++nLoose;
  }
  if (nLoose < 2) return;
  const int freeBefore = countFreeEdges(loose);
  if (freeBefore == 0) return;
  try {
    BRepBuilderAPI_Sewing sewing(tol, /*option1 sewing*/ true, /*analysis*/ true,
                                 /*cutting*/ true, /*nonmanifold*/ false);
    sewing.Add(loose);
    sewing.Perform();
    const TopoDS_Shape sewn = sewing.SewedShape();
    if (sewn.IsNull() || countFreeEdges(sewn) >= freeBefore) return;
    for (TopExp_Explorer s(impl.shape, TopAbs_SOLID); s.More(); s.Next()) b.Add(solids, s.Current());
    b.Add(solids, sewn);
    const TopoDS_Shape before = impl.shape;
    impl.shape = solids;
    carryFaceTags(impl, before, [&sewing](const TopoDS_Shape& f) {
      return imageList(sewing.IsModifiedSubShape(f) ? sewing.ModifiedSubShape(f) : f);
    });
    dropStaleFaceTags(impl);
    report.facesSewn = nLoose;
  } catch (const Standard_Failure& e) {
    report.warnings.push_back(std::string("sewing failed (") + e.GetMessageString() +
                              "); loose faces are kept as they are");
  }
}

}  // namespace aniso::cad::detail
