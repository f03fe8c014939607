// OcctCurve2d: ParametricCurve2d over an OCCT pcurve (see OcctCurve2d.h).
#include "cad/OcctCurve2d.h"

#include <BRep_Tool.hxx>
#include <TopoDS.hxx>

namespace aniso::cad {

OcctCurve2d::OcctCurve2d(const TopoDS_Edge& edge, const TopoDS_Face& face, std::string name)
    : name_(std::move(name)) {
  detail::loadOcctCurve(name_, "pcurve", [&] {
    const TopoDS_Face forwardFace = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
    curve_ = BRep_Tool::CurveOnSurface(edge, forwardFace, range_.first, range_.last);
    if (curve_.IsNull()) throw MeshingError(name_ + ": the edge has no pcurve on the face");
    range_.cover(curve_->FirstParameter(), curve_->LastParameter());
    adaptor_ = new Geom2dAdaptor_Curve(curve_);
  });
}

OcctCurve2d::OcctCurve2d(const OcctCurve2d& other)
    : ParametricCurve2d(other), curve_(other.curve_), range_(other.range_), name_(other.name_) {
  // a new cache over the shared geometry
  detail::loadOcctCurve(name_, "pcurve", [this] { adaptor_ = new Geom2dAdaptor_Curve(curve_); });
}

std::unique_ptr<ParametricCurve2d> OcctCurve2d::clone() const {
  return std::unique_ptr<ParametricCurve2d>(new OcctCurve2d(*this));
}

Vec2 OcctCurve2d::point(double t) const { return detail::occtCurvePoint<gp_Pnt2d>(*adaptor_, t, name_, "pcurve"); }

Curve2dD2 OcctCurve2d::d2(double t) const {
  return detail::occtCurveD2<Curve2dD2, gp_Pnt2d, gp_Vec2d>(*adaptor_, t, name_, "pcurve");
}

}  // namespace aniso::cad
