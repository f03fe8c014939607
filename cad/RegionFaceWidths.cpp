#include <BOPTools_AlgoTools3D.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <IntTools_Context.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <limits>
#include <memory>

#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {
namespace {

/// 2 × area / perimeter: the width of a strip, about the inradius of a compact face.
double faceWidth(const TopoDS_Face& face) {
  GProp_GProps area, length;
  BRepGProp::SurfaceProperties(face, area);
  BRepGProp::LinearProperties(face, length);
  return length.Mass() > 0 ? 2 * area.Mass() / length.Mass() : 0;
}

}  // namespace

std::vector<double> regionFaceWidths(const TopoDS_Shape& region, const std::vector<TopoDS_Shape>& parts, double tol) {
  constexpr double kNone = std::numeric_limits<double>::infinity();
  std::vector<double> width(parts.size(), kNone);
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(region, TopAbs_FACE, faces);
  Handle(IntTools_Context) context = new IntTools_Context;
  std::vector<std::unique_ptr<BRepClass3d_SolidClassifier>> classifier;  // one per part: built once
  for (const TopoDS_Shape& part : parts) classifier.push_back(std::make_unique<BRepClass3d_SolidClassifier>(part));
  for (int k = 1; k <= faces.Extent(); ++k) {
    try {
      const TopoDS_Face& face = TopoDS::Face(faces(k));
      gp_Pnt p;
      gp_Pnt2d uv;
      if (BOPTools_AlgoTools3D::PointInFace(face, p, uv, context) != 0) continue;
      const double w = faceWidth(face);
      const double onTol = std::max(tol, BRep_Tool::Tolerance(face));
      for (std::size_t i = 0; i < parts.size(); ++i) {
        classifier[i]->Perform(p, onTol);
        if (classifier[i]->State() == TopAbs_ON) width[i] = std::min(width[i], w);
      }
    } catch (const Standard_Failure&) {
      // a face OCCT cannot measure or classify says nothing about the choice
    }
  }
  return width;
}

}  // namespace aniso::cad::detail
