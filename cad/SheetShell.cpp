#include "cad/detail/SheetShell.h"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS_Face.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopLoc_Location.hxx>
#include <gp_XYZ.hxx>


namespace aniso::cad::detail {

double vectorAreaRatio(const TopoDS_Shape& shell) {
  try {
    // A coarse triangulation of a copy (the model's faces keep none): Σ ±(b − a) × (c − a) / 2
    // and Σ of the areas, each face's triangles turned as the face is in the shell.
    const TopoDS_Shape copy = BRepBuilderAPI_Copy(shell).Shape();
    BRepMesh_IncrementalMesh mesher(copy, kSheetMeshDeflection, true, 0.5);
    gp_XYZ sum(0, 0, 0);
    double area = 0;
    for (TopExp_Explorer x(copy, TopAbs_FACE); x.More(); x.Next()) {
      const TopoDS_Face face = TopoDS::Face(x.Current());
      TopLoc_Location loc;
      const Handle(Poly_Triangulation) t = BRep_Tool::Triangulation(face, loc);
      if (t.IsNull()) return 0;
      const double sign = face.Orientation() == TopAbs_REVERSED ? -1 : 1;
      for (int k = 1; k <= t->NbTriangles(); ++k) {
        int i, j, l;
        t->Triangle(k).Get(i, j, l);
        const gp_XYZ a = t->Node(i).Transformed(loc.Transformation()).XYZ();
        const gp_XYZ n = (t->Node(j).Transformed(loc.Transformation()).XYZ() - a)
                             .Crossed(t->Node(l).Transformed(loc.Transformation()).XYZ() - a);
        sum += sign * 0.5 * n;
        area += 0.5 * n.Modulus();
      }
    }
    return area > 0 ? sum.Modulus() / area : 0;
  } catch (const Standard_Failure&) {
    return 0;
  }
}

bool isSheetShell(const TopoDS_Shape& shell) {
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndAncestors(shell, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  bool open = false;
  for (int i = 1; i <= edgeFaces.Extent() && !open; ++i) {
    if (BRep_Tool::Degenerated(TopoDS::Edge(edgeFaces.FindKey(i)))) continue;
    TopTools_IndexedMapOfShape distinct;
    for (const TopoDS_Shape& f : edgeFaces(i)) distinct.Add(f);
    open = distinct.Extent() == 1 && !BRep_Tool::IsClosed(TopoDS::Edge(edgeFaces.FindKey(i)), TopoDS::Face(distinct(1)));
  }
  return open && vectorAreaRatio(shell) >= kSheetVectorArea;
}

}  // namespace aniso::cad::detail
