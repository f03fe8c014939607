#include <BOPAlgo_BuilderSolid.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>

#include <cmath>

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

double solidVolume(const TopoDS_Shape& solid) {
  try {
    GProp_GProps g;
    BRepGProp::VolumeProperties(solid, g);
    return g.Mass();
  } catch (const Standard_Failure&) {
    return 0;
  }
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
