#pragma once
// Shapes and checks shared by the tests of the OCCT adapters and of buildTopology.
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <cmath>
#include <functional>
#include <stdexcept>

#include "mesher/core/Types.h"

namespace aniso::cad::test {

inline const double kPi = std::acos(-1.0);

/// The first face of `shape` whose surface is of type `type`.
inline TopoDS_Face faceOfType(const TopoDS_Shape& shape, GeomAbs_SurfaceType type) {
  for (TopExp_Explorer x(shape, TopAbs_FACE); x.More(); x.Next()) {
    const TopoDS_Face& f = TopoDS::Face(x.Current());
    if (BRepAdaptor_Surface(f, false).GetType() == type) return f;
  }
  throw std::runtime_error("no face of the requested type");
}

/// A non-planar, non-periodic B-spline patch over [0,4]×[0,3] (a wavy sheet), as a face.
inline TopoDS_Face bsplineFace() {
  TColgp_Array2OfPnt pts(1, 7, 1, 6);
  for (int i = 1; i <= 7; ++i)
    for (int j = 1; j <= 6; ++j) {
      const double x = 4.0 * (i - 1) / 6, y = 3.0 * (j - 1) / 5;
      pts(i, j) = gp_Pnt(x, y, 0.4 * std::sin(1.3 * x) * std::cos(0.9 * y) + 0.1 * x * y);
    }
  GeomAPI_PointsToBSplineSurface fit(pts);
  return BRepBuilderAPI_MakeFace(fit.Surface(), 1e-7).Face();
}

/// Central difference of a vector function of one variable.
template <class F>
auto centralDifference(F f, double t, double h) {
  return ((f(t + h) - f(t - h)) / (2 * h)).eval();
}

}  // namespace aniso::cad::test
