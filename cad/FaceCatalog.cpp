#include "cad/FaceCatalog.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>

#include "cad/detail/CadModelImpl.h"
#include "cad/detail/ShapeSummary.h"

namespace aniso::cad {
namespace {

const char* surfaceTypeName(GeomAbs_SurfaceType t) {
  switch (t) {
    case GeomAbs_Plane: return "plane";
    case GeomAbs_Cylinder: return "cylinder";
    case GeomAbs_Cone: return "cone";
    case GeomAbs_Sphere: return "sphere";
    case GeomAbs_Torus: return "torus";
    case GeomAbs_BezierSurface: return "bezier";
    case GeomAbs_BSplineSurface: return "bspline";
    case GeomAbs_SurfaceOfRevolution: return "revolution";
    case GeomAbs_SurfaceOfExtrusion: return "extrusion";
    case GeomAbs_OffsetSurface: return "offset";
    default: return "other";
  }
}

const char* curveTypeName(GeomAbs_CurveType t) {
  switch (t) {
    case GeomAbs_Line: return "line";
    case GeomAbs_Circle: return "circle";
    case GeomAbs_Ellipse: return "ellipse";
    case GeomAbs_Hyperbola: return "hyperbola";
    case GeomAbs_Parabola: return "parabola";
    case GeomAbs_BezierCurve: return "bezier";
    case GeomAbs_BSplineCurve: return "bspline";
    case GeomAbs_OffsetCurve: return "offset";
    default: return "other";
  }
}

/// 1-based indices in `map` of the shapes `ancestors` lists for `s`, ascending and distinct.
std::vector<int> ancestorIds(const TopTools_IndexedDataMapOfShapeListOfShape& ancestors, const TopoDS_Shape& s,
                             const TopTools_IndexedMapOfShape& map) {
  std::vector<int> ids;
  const int k = ancestors.FindIndex(s);
  if (k == 0) return ids;
  for (const TopoDS_Shape& a : ancestors(k))
    if (const int i = map.FindIndex(a)) ids.push_back(i);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

/// Measure and centroid: `surface` for a face's area, else an edge's length.
void measure(const TopoDS_Shape& s, bool surface, CatalogEntry& e) {
  try {
    GProp_GProps g;
    if (surface) BRepGProp::SurfaceProperties(s, g);
    else BRepGProp::LinearProperties(s, g);
    e.measure = g.Mass();
    const gp_Pnt c = g.CentreOfMass();
    if (e.measure > 0) e.centroid = Vec3(c.X(), c.Y(), c.Z());
  } catch (const Standard_Failure&) {
    e.measure = 0;
  }
}

}  // namespace

FaceCatalog faceCatalog(const CadModel& model) {
  const CadModel::Impl& impl = model.impl();
  const TopoDS_Shape& shape = impl.shape;
  TopTools_IndexedMapOfShape solids, faces, edges;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  TopTools_IndexedDataMapOfShapeListOfShape faceSolids, edgeSolids, edgeFaces;
  TopExp::MapShapesAndAncestors(shape, TopAbs_FACE, TopAbs_SOLID, faceSolids);
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_SOLID, edgeSolids);
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  const auto partOf = [&](const std::vector<int>& ids) {
    return ids.empty() ? std::string() : impl.solidName(solids(ids.front()), ids.front());
  };
  FaceCatalog c;
  for (int i = 1; i <= faces.Extent(); ++i) {
    CatalogEntry e;
    e.id = i;
    try {
      e.type = surfaceTypeName(BRepAdaptor_Surface(TopoDS::Face(faces(i))).GetType());
    } catch (const Standard_Failure&) {
      e.type = "other";
    }
    measure(faces(i), true, e);
    e.bbox = detail::exactBoundingBox(faces(i));
    e.solids = ancestorIds(faceSolids, faces(i), solids);
    e.part = partOf(e.solids);
    if (const FaceTag* tag = impl.faceTag(faces(i))) {
      e.name = tag->name;
      e.color = tag->color;
    }
    c.faces.push_back(std::move(e));
  }
  for (int i = 1; i <= edges.Extent(); ++i) {
    CatalogEntry e;
    e.id = i;
    const TopoDS_Edge& edge = TopoDS::Edge(edges(i));
    if (BRep_Tool::Degenerated(edge)) {
      e.type = "degenerated";
    } else {
      try {
        e.type = curveTypeName(BRepAdaptor_Curve(edge).GetType());
      } catch (const Standard_Failure&) {
        e.type = "other";
      }
      measure(edge, false, e);
    }
    e.bbox = detail::exactBoundingBox(edge);
    e.solids = ancestorIds(edgeSolids, edge, solids);
    e.faces = ancestorIds(edgeFaces, edge, faces);
    e.part = partOf(e.solids);
    c.edges.push_back(std::move(e));
  }
  return c;
}

}  // namespace aniso::cad
