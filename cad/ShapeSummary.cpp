#include "cad/detail/ShapeSummary.h"

#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>

#include <cmath>

namespace aniso::cad::detail {

namespace {
/// accurateVolume's relative error bound. At 1e-5: 1.4 s for the 35 solids of
/// assembly_workbench (the fixed-order integral 0.2 s).
constexpr double kVolumeIntegralRel = 1e-5;
}  // namespace

double accurateVolume(const TopoDS_Shape& solid) {
  try {
    GProp_GProps fixed, adaptive;
    BRepGProp::VolumeProperties(solid, fixed);
    BRepGProp::VolumeProperties(solid, adaptive, kVolumeIntegralRel);
    // within the adaptive integral's bound the fixed-order one is kept: exact to rounding
    // on planes, cylinders and the like, where the adaptive one is only within its bound
    const double a = adaptive.Mass();
    return std::abs(fixed.Mass() - a) <= kVolumeIntegralRel * std::abs(a) ? fixed.Mass() : a;
  } catch (const Standard_Failure&) {
    return 0;
  }
}

double solidVolumeOf(const CadModel::Impl& impl, const TopoDS_Shape& solid) {
  // instances of one part (one TShape, several locations) are integrated once, unplaced;
  // a placement that scales scales the volume by the cube of its factor
  const TopoDS_Shape part = solid.Located(TopLoc_Location());
  const double scale = std::pow(std::abs(solid.Location().Transformation().ScaleFactor()), 3);
  if (const double* v = impl.volumes.Seek(part)) return *v * scale;
  const double v = accurateVolume(part);
  impl.volumes.Bind(part, v);
  return v * scale;
}

Box3 exactBoundingBox(const TopoDS_Shape& shape) {
  Box3 box;
  Bnd_Box b;
  // BRepBndLib::Add bounds B-spline geometry by its poles, and AddOptimal (exact) costs
  // seconds on large models; the box only sets relative sizes, so Add is used, without
  // the shape tolerances.
  try {
    BRepBndLib::Add(shape, b, /*useTriangulation=*/false);
  } catch (const Standard_Failure&) {
    b.SetVoid();
  }
  if (b.IsVoid()) return box;
  double x0, y0, z0, x1, y1, z1;
  b.Get(x0, y0, z0, x1, y1, z1);
  box.add(Vec3(x0, y0, z0));
  box.add(Vec3(x1, y1, z1));
  return box;
}

ShapeSummary summarize(const CadModel::Impl& impl) {
  ShapeSummary s;
  const TopoDS_Shape& shape = impl.shape;
  TopTools_IndexedMapOfShape solids, shells, faces, edges, vertices;
  TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  TopExp::MapShapes(shape, TopAbs_SHELL, shells);
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  TopExp::MapShapes(shape, TopAbs_VERTEX, vertices);
  s.solids = solids.Extent();
  s.shells = shells.Extent();
  s.faces = faces.Extent();
  s.edges = edges.Extent();
  s.vertices = vertices.Extent();
  for (int i = 1; i <= solids.Extent(); ++i) {
    const double v = solidVolumeOf(impl, solids(i));
    s.volume += v;
    s.solidList.push_back({i, impl.solidName(solids(i), i), v, impl.solidColor(solids(i))});
  }
  // area: every face occurrence, as OCCT's GProp integrates a shape (a face shared by two
  // solids counts twice); uniqueFaceArea: every face once.
  try {
    GProp_GProps g;
    BRepGProp::SurfaceProperties(shape, g);
    s.area = g.Mass();
  } catch (const Standard_Failure&) {
    s.area = 0;
  }
  TopTools_IndexedDataMapOfShapeListOfShape faceSolids;
  TopExp::MapShapesAndAncestors(shape, TopAbs_FACE, TopAbs_SOLID, faceSolids);
  for (int i = 1; i <= faces.Extent(); ++i) {
    GProp_GProps g;
    try {
      BRepGProp::SurfaceProperties(faces(i), g);
    } catch (const Standard_Failure&) {
      continue;
    }
    s.uniqueFaceArea += g.Mass();
    const int k = faceSolids.FindIndex(faces(i));
    if (k == 0) continue;
    TopTools_IndexedMapOfShape distinct;
    for (const TopoDS_Shape& so : faceSolids(k)) distinct.Add(so);
    if (distinct.Extent() == 1) s.exposedArea += g.Mass();
  }
  s.bbox = exactBoundingBox(shape);
  return s;
}

}  // namespace aniso::cad::detail
