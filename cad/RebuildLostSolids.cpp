// A solid the STEP file declares (MANIFOLD_SOLID_BREP, FACETED_BREP) whose boundary the file
// stores as an OPEN_SHELL: OCCT's transfer keeps its faces but no solid. When those faces
// close (sewn within a tolerance relative to their size), the solid is rebuilt from them.
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepGProp.hxx>
#include <BRep_Builder.hxx>
#include <GProp_GProps.hxx>
#include <ShapeFix_Solid.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <vector>

#include "cad/detail/Prepare.h"
#include "cad/detail/Readers.h"
#include "cad/detail/ShapeSummary.h"

namespace aniso::cad::detail {

namespace {

/// Sewing tolerance for the loose faces, relative to their size: closes the rounding gaps of
/// a writer, never a real opening.
constexpr double kRebuildSewRel = 1e-6;

/// The faces of `shape` outside any solid, once each.
TopoDS_Compound looseFaces(const TopoDS_Shape& shape, int& count) {
  TopTools_IndexedMapOfShape inSolid, seen;
  for (TopExp_Explorer s(shape, TopAbs_SOLID); s.More(); s.Next()) TopExp::MapShapes(s.Current(), TopAbs_FACE, inSolid);
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  count = 0;
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
    if (inSolid.Contains(f.Current()) || seen.Contains(f.Current())) continue;
    seen.Add(f.Current());
    b.Add(c, f.Current());
    ++count;
  }
  return c;
}

/// A solid bounded by the closed shell, turned so that its volume is positive; null if
/// OCCT cannot make one or it encloses no volume.
TopoDS_Solid solidOf(const TopoDS_Shell& shell, double diag) {
  BRepBuilderAPI_MakeSolid make(shell);
  if (!make.IsDone()) return {};
  ShapeFix_Solid fix(make.Solid());
  fix.Perform();
  TopoDS_Solid solid;
  for (TopExp_Explorer s(fix.Solid(), TopAbs_SOLID); s.More() && solid.IsNull(); s.Next()) solid = TopoDS::Solid(s.Current());
  if (solid.IsNull()) return {};
  GProp_GProps props;
  BRepGProp::VolumeProperties(solid, props);
  if (!(props.Mass() > 1e-12 * diag * diag * diag)) return {};
  return solid;
}

}  // namespace

int rebuildLostSolids(TopoDS_Shape& shape, int lost) {
  if (lost <= 0 || shape.IsNull()) return 0;
  try {
    int nLoose = 0;
    const TopoDS_Compound loose = looseFaces(shape, nLoose);
    if (nLoose == 0) return 0;
    const double diag = exactBoundingBox(loose).diagonal();
    if (!(diag > 0)) return 0;
    BRepBuilderAPI_Sewing sewing(kRebuildSewRel * diag);
    sewing.Add(loose);
    sewing.Perform();
    const TopoDS_Shape sewn = sewing.SewedShape();
    if (sewn.IsNull()) return 0;
    // The closed shells among the sewn faces; the rebuild must be unambiguous: no more
    // closed shells than solids the transfer lost.
    std::vector<TopoDS_Shell> closed;
    for (TopExp_Explorer s(sewn, TopAbs_SHELL); s.More(); s.Next())
      if (countFreeEdges(s.Current()) == 0) closed.push_back(TopoDS::Shell(s.Current()));
    if (closed.empty() || static_cast<int>(closed.size()) > lost) return 0;
    std::vector<TopoDS_Solid> solids;
    for (const TopoDS_Shell& shell : closed) {
      const TopoDS_Solid solid = solidOf(shell, diag);
      if (solid.IsNull()) return 0;
      solids.push_back(solid);
    }
    // The new shape: the solids as read, the rebuilt ones, then what else the sewn faces
    // and the file held outside faces (free edges and vertices are kept as they were).
    TopTools_IndexedMapOfShape used;
    for (const TopoDS_Solid& s : solids) TopExp::MapShapes(s, TopAbs_FACE, used);
    BRep_Builder b;
    TopoDS_Compound out;
    b.MakeCompound(out);
    for (TopExp_Explorer s(shape, TopAbs_SOLID); s.More(); s.Next()) b.Add(out, s.Current());
    for (const TopoDS_Solid& s : solids) b.Add(out, s);
    for (TopExp_Explorer f(sewn, TopAbs_FACE); f.More(); f.Next())
      if (!used.Contains(f.Current())) b.Add(out, f.Current());
    for (TopExp_Explorer e(shape, TopAbs_EDGE, TopAbs_FACE); e.More(); e.Next()) b.Add(out, e.Current());
    for (TopExp_Explorer v(shape, TopAbs_VERTEX, TopAbs_EDGE); v.More(); v.Next()) b.Add(out, v.Current());
    shape = out;
    return static_cast<int>(solids.size());
  } catch (const Standard_Failure&) {
    return 0;
  }
}

}  // namespace aniso::cad::detail
