#include <BOPAlgo_BuilderSolid.hxx>
#include <BRep_Builder.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>

#include <cmath>
#include <cstdio>

#include "cad/detail/Prepare.h"

namespace aniso::cad::detail {
namespace {

/// The merged solids may differ from the pieces only by integration error (OCCT integrates
/// B-spline faces to about 1e-5 relative).
constexpr double kMergeVolumeRel = 1e-3;

double volumeOfList(const TopTools_ListOfShape& solids) {
  double v = 0;
  for (const TopoDS_Shape& s : solids) v += solidVolume(s);
  return v;
}

}  // namespace

namespace {

/// GProp's mass of the shape (its volume, or with `area` its faces' area); 0 if OCCT fails.
double mass(const TopoDS_Shape& shape, bool area) {
  try {
    GProp_GProps g;
    if (area) BRepGProp::SurfaceProperties(shape, g);
    else BRepGProp::VolumeProperties(shape, g);
    return g.Mass();
  } catch (const Standard_Failure&) {
    return 0;
  }
}

}  // namespace

double solidVolume(const TopoDS_Shape& solid) { return mass(solid, false); }

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}
double shapeArea(const TopoDS_Shape& shape) { return mass(shape, true); }

void addLooseFaces(const TopoDS_Shape& shape, const TopTools_IndexedMapOfShape& solids, TopoDS_Compound& c) {
  TopTools_IndexedMapOfShape inSolid, allFaces;
  for (int i = 1; i <= solids.Extent(); ++i) TopExp::MapShapes(solids(i), TopAbs_FACE, inSolid);
  TopExp::MapShapes(shape, TopAbs_FACE, allFaces);
  BRep_Builder b;
  for (int i = 1; i <= allFaces.Extent(); ++i)
    if (!inSolid.Contains(allFaces(i))) b.Add(c, allFaces(i));
}

TopTools_ListOfShape mergePieces(const TopTools_ListOfShape& pieces, double partVolume) {
  if (pieces.Extent() < 2) return pieces;
  // A face bounding two of the pieces is inside the part: dropped. The others keep their
  // orientation in their piece, and their TShape (shared with the neighbouring parts).
  TopTools_IndexedDataMapOfShapeListOfShape faceUses;
  for (const TopoDS_Shape& piece : pieces)
    for (TopExp_Explorer f(piece, TopAbs_FACE); f.More(); f.Next()) {
      if (!faceUses.Contains(f.Current())) faceUses.Add(f.Current(), TopTools_ListOfShape());
      faceUses.ChangeFromKey(f.Current()).Append(f.Current());
    }
  TopTools_ListOfShape boundary;
  for (int i = 1; i <= faceUses.Extent(); ++i)
    if (faceUses(i).Extent() == 1) boundary.Append(faceUses(i).First());
  try {
    BOPAlgo_BuilderSolid builder;
    builder.SetShapes(boundary);
    builder.SetRunParallel(false);
    builder.SetAvoidInternalShapes(true);
    builder.Perform();
    const double before = volumeOfList(pieces), after = volumeOfList(builder.Areas());
    if (builder.HasErrors() || builder.HasWarnings() || builder.Areas().IsEmpty()) return pieces;
    const double slack = kMergeVolumeRel * std::abs(before);
    if (std::abs(after - before) > slack && std::abs(after - partVolume) > slack) return pieces;
    return builder.Areas();
  } catch (const Standard_Failure&) {
    return pieces;
  }
}

}  // namespace aniso::cad::detail
