#include <BRepCheck_Analyzer.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Pnt2d.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>

#include <cmath>

#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {
namespace {

/// A loop is open when two consecutive edges miss each other in (u,v) by more than this
/// fraction of the face's parametric extent: the face mesher's bar for a loop whose ends
/// are one point in 3D (kLoopGapWithinTolerance, mesher/surface/contour/FaceLoops.cpp).
constexpr double kOpenLoopRel = 0.1;

/// (u,v) of the start (or end) of an edge as the wire runs it.
gp_Pnt2d uvEnd(const TopoDS_Edge& e, const TopoDS_Face& face, bool start) {
  gp_Pnt2d first, last;
  BRep_Tool::UVPoints(e, face, first, last);
  const bool reversed = e.Orientation() == TopAbs_REVERSED;
  return start != reversed ? first : last;
}

bool hasOpenLoop(const TopoDS_Face& face) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  const double extent = std::hypot(u1 - u0, v1 - v0);
  if (!(std::isfinite(extent) && extent > 0)) return false;
  const BRepAdaptor_Surface surf(face, false);
  const double pu = surf.IsUPeriodic() ? surf.UPeriod() : 0, pv = surf.IsVPeriodic() ? surf.VPeriod() : 0;
  const auto gap = [&](const gp_Pnt2d& a, const gp_Pnt2d& b) {
    double du = b.X() - a.X(), dv = b.Y() - a.Y();
    if (pu > 0) du -= pu * std::round(du / pu);
    if (pv > 0) dv -= pv * std::round(dv / pv);
    return std::hypot(du, dv);
  };
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
    const TopoDS_Wire& wire = TopoDS::Wire(w.Current());
    int edges = 0, visited = 0;
    for (TopExp_Explorer e(wire, TopAbs_EDGE); e.More(); e.Next()) ++edges;
    gp_Pnt2d first, previous;
    for (BRepTools_WireExplorer x(wire, face); x.More(); x.Next(), ++visited) {
      const TopoDS_Edge& e = x.Current();
      if (visited == 0)
        first = uvEnd(e, face, true);
      else if (gap(previous, uvEnd(e, face, true)) > kOpenLoopRel * extent)
        return true;
      previous = uvEnd(e, face, false);
    }
    if (visited < edges || (visited > 0 && gap(previous, first) > kOpenLoopRel * extent)) return true;
  }
  return false;
}

}  // namespace

int countOpenLoopFaces(const TopoDS_Shape& shape) {
  int open = 0;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    try {
      const TopoDS_Face& face = TopoDS::Face(e.Current());
      if (hasOpenLoop(face) || !BRepCheck_Analyzer(face, /*GeomControls=*/false).IsValid()) ++open;
    } catch (const Standard_Failure&) {
      ++open;
    }
  }
  return open;
}

}  // namespace aniso::cad::detail
