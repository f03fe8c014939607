// OcctCurve3d: ParametricCurve3d over an OCCT edge's 3D geometry (see OcctCurve3d.h).
#include "cad/OcctCurve3d.h"

#include <Adaptor3d_CurveOnSurface.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <TopLoc_Location.hxx>

namespace aniso::cad {

OcctCurve3d::OcctCurve3d(const TopoDS_Edge& edge, std::string name) : name_(std::move(name)) {
  detail::loadOcctCurve(name_, "curve", [&] {
    if (BRep_Tool::Degenerated(edge))
      throw MeshingError(name_ + ": a degenerate edge has no 3D curve");
    double natFirst = 0, natLast = 0;
    curve_ = BRep_Tool::Curve(edge, range_.first, range_.last);  // a transformed copy under a location
    if (!curve_.IsNull()) {
      natFirst = curve_->FirstParameter();
      natLast = curve_->LastParameter();
    } else {
      TopLoc_Location loc;
      BRep_Tool::CurveOnSurface(edge, pcurve_, surface_, loc, range_.first, range_.last, 1);
      if (pcurve_.IsNull() || surface_.IsNull())
        throw MeshingError(name_ + ": the edge has neither a 3D curve nor a pcurve");
      if (!loc.IsIdentity())
        surface_ = Handle(Geom_Surface)::DownCast(surface_->Transformed(loc.Transformation()));
      natFirst = pcurve_->FirstParameter();
      natLast = pcurve_->LastParameter();
    }
    range_.cover(natFirst, natLast);
    makeAdaptor();
  });
}

OcctCurve3d::OcctCurve3d(const OcctCurve3d& other)
    : ParametricCurve3d(other),
      curve_(other.curve_),
      pcurve_(other.pcurve_),
      surface_(other.surface_),
      range_(other.range_),
      name_(other.name_) {
  detail::loadOcctCurve(name_, "curve", [this] { makeAdaptor(); });  // new caches over the shared geometry
}

void OcctCurve3d::makeAdaptor() {
  if (!curve_.IsNull()) {
    adaptor_ = new GeomAdaptor_Curve(curve_);
    return;
  }
  Handle(Geom2dAdaptor_Curve) pc = new Geom2dAdaptor_Curve(pcurve_);
  Handle(GeomAdaptor_Surface) s = new GeomAdaptor_Surface(surface_);
  adaptor_ = new Adaptor3d_CurveOnSurface(pc, s);
}

std::unique_ptr<ParametricCurve3d> OcctCurve3d::clone() const {
  return std::unique_ptr<ParametricCurve3d>(new OcctCurve3d(*this));
}

Vec3 OcctCurve3d::point(double t) const { return detail::occtCurvePoint<gp_Pnt>(*adaptor_, t, name_, "curve"); }

Curve3dD2 OcctCurve3d::d2(double t) const {
  return detail::occtCurveD2<Curve3dD2, gp_Pnt, gp_Vec>(*adaptor_, t, name_, "curve");
}

}  // namespace aniso::cad
