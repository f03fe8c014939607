#include "cad/FalsePole.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_Curve.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <cmath>

namespace aniso::cad {
namespace {

constexpr double kFalsePoleTolFactor = 10;
constexpr double kFalsePoleRel = 1e-3;

}  // namespace

bool falsePole(const TopoDS_Edge& edge, const TopoDS_Face& face) {
  if (!BRep_Tool::Degenerated(edge)) return false;
  double a = 0, b = 0;
  const Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(edge, face, a, b);
  TopoDS_Vertex v0, v1;
  TopExp::Vertices(edge, v0, v1);
  if (pc.IsNull() || v0.IsNull()) return false;
  Bnd_Box box;
  BRepBndLib::Add(face, box);
  const double size = box.IsVoid() ? 0 : std::sqrt(box.SquareExtent());
  const double tol = std::max(kFalsePoleTolFactor * BRep_Tool::Tolerance(edge), kFalsePoleRel * size);
  const gp_Pnt p = BRep_Tool::Pnt(v0);
  const BRepAdaptor_Surface surface(face, false);  // the face's own location, no restriction
  double stray = 0;
  for (int k = 0; k <= 4; ++k) {
    const gp_Pnt2d uv = pc->Value(a + 0.25 * k * (b - a));
    stray = std::max(stray, surface.Value(uv.X(), uv.Y()).Distance(p));
  }
  return stray > tol;
}

int facesBoundedByFalsePoles(const TopoDS_Shape& shape) {
  int count = 0;
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face face = TopoDS::Face(faces(i).Oriented(TopAbs_FORWARD));
    bool counted = false;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More() && !counted; w.Next()) {
      bool onlyPolesAndSeams = true, anyFalse = false;
      for (TopExp_Explorer e(w.Current(), TopAbs_EDGE); e.More() && onlyPolesAndSeams; e.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
        if (BRep_Tool::Degenerated(edge))
          anyFalse = anyFalse || falsePole(TopoDS::Edge(edge.Oriented(TopAbs_FORWARD)), face);
        else
          onlyPolesAndSeams = BRep_Tool::IsClosed(edge, face);
      }
      counted = onlyPolesAndSeams && anyFalse;
    }
    count += counted;
  }
  return count;
}

}  // namespace aniso::cad
