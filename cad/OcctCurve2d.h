#pragma once
// Internal: the thesis' ParametricCurve2d (sec. 6.2.2) over the pcurve of an OCCT edge on a
// face (BRep_Tool::CurveOnSurface).
//
// The pcurve lives in the parametric plane of the face's surface, i.e. of the OcctSurface
// built from the same face. On a seam (an edge with two pcurves on the face) the edge's
// orientation selects the pcurve: FORWARD the first, REVERSED the second — BRep_Tool's
// convention with the face taken FORWARD (the face's own orientation is ignored here, so
// the choice does not flip with it).
//
// Thread safety as for OcctSurface: the Geom2dAdaptor_Curve keeps a B-spline cache, clone()
// builds a new one over the same immutable geometry.
// Errors: OCCT exceptions become MeshingError naming the edge and face.
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_Curve.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>

#include <memory>
#include <string>

#include "cad/detail/OcctCurveCommon.h"
#include "mesher/geometry/ParametricCurve2d.h"

namespace aniso::cad {

class OcctCurve2d final : public ParametricCurve2d {
 public:
  /// The pcurve of `edge` on `face` (see above for seams). `name` names the pair in errors
  /// ("edge 4 on face 2"). Throws MeshingError when the edge has no pcurve on the face.
  OcctCurve2d(const TopoDS_Edge& edge, const TopoDS_Face& face, std::string name);

  Vec2 point(double t) const override;
  Curve2dD2 d2(double t) const override;
  /// The curve's natural range, extended to cover the edge's range (a periodic curve's edge
  /// may run past its period); an infinite end (lines) is the edge's end.
  double tMin() const override { return range_.tMin; }
  double tMax() const override { return range_.tMax; }
  std::unique_ptr<ParametricCurve2d> clone() const override;

  /// The parameter range the edge uses on this face.
  double first() const { return range_.first; }
  double last() const { return range_.last; }
  const std::string& name() const { return name_; }

 private:
  OcctCurve2d(const OcctCurve2d& other);

  Handle(Geom2d_Curve) curve_;
  Handle(Geom2dAdaptor_Curve) adaptor_;
  detail::OcctCurveRange range_;
  std::string name_;
};

}  // namespace aniso::cad
