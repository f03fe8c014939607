#pragma once
// Internal: the thesis' ParametricCurve3d (fig. 6.3) over the 3D geometry of an OCCT edge.
//
// The curve is BRep_Tool::Curve with the edge's location applied. An edge without a 3D curve
// (some IGES files) is evaluated through its first curve on a surface (pcurve composed with
// the surface, Adaptor3d_CurveOnSurface). Degenerate edges have no 3D geometry: Model keeps
// a null curve for them and this class refuses them.
//
// Thread safety as for OcctSurface: clone() builds new adaptors over the same immutable
// geometry. Errors: OCCT exceptions become MeshingError naming the edge.
#include <Adaptor3d_Curve.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Curve.hxx>
#include <Geom_Surface.hxx>
#include <TopoDS_Edge.hxx>

#include <memory>
#include <string>

#include "cad/detail/OcctCurveCommon.h"
#include "mesher/geometry/ParametricCurve3d.h"

namespace aniso::cad {

class OcctCurve3d final : public ParametricCurve3d {
 public:
  /// The 3D curve of `edge` (orientation ignored: parameters run as stored). `name` names
  /// the edge in errors ("edge 4"). Throws MeshingError for a degenerate edge or an edge
  /// with no geometry at all.
  OcctCurve3d(const TopoDS_Edge& edge, std::string name);

  Vec3 point(double t) const override;
  Curve3dD2 d2(double t) const override;
  /// Natural range extended to cover the edge's range; infinite ends are the edge's ends.
  double tMin() const override { return range_.tMin; }
  double tMax() const override { return range_.tMax; }
  std::unique_ptr<ParametricCurve3d> clone() const override;

  /// The parameter range of the edge.
  double first() const { return range_.first; }
  double last() const { return range_.last; }
  /// True when evaluated through a curve on a surface (the edge has no 3D curve).
  bool onSurface() const { return curve_.IsNull(); }
  const std::string& name() const { return name_; }

 private:
  OcctCurve3d(const OcctCurve3d& other);
  void makeAdaptor();

  Handle(Geom_Curve) curve_;       ///< the 3D curve (location applied), or null
  Handle(Geom2d_Curve) pcurve_;    ///< else: a pcurve ...
  Handle(Geom_Surface) surface_;   ///< ... on this surface (location applied)
  Handle(Adaptor3d_Curve) adaptor_;
  detail::OcctCurveRange range_;
  std::string name_;
};

}  // namespace aniso::cad
