// OcctCurve2d: ParametricCurve2d over an OCCT pcurve (see OcctCurve2d.h).
#include "cad/OcctCurve2d.h"

#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopoDS.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec2d.hxx>

#include <algorithm>
#include <sstream>

#include "mesher/core/Error.h"

namespace aniso::cad {
namespace {

std::string occtMessage(const Standard_Failure& e) {
  const char* m = e.GetMessageString();
  return (m && *m) ? std::string(m) : std::string(e.DynamicType()->Name());
}

}  // namespace

OcctCurve2d::OcctCurve2d(const TopoDS_Edge& edge, const TopoDS_Face& face, std::string name)
    : name_(std::move(name)) {
  try {
    const TopoDS_Face forwardFace = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
    curve_ = BRep_Tool::CurveOnSurface(edge, forwardFace, first_, last_);
    if (curve_.IsNull()) throw MeshingError(name_ + ": the edge has no pcurve on the face");
    const double natFirst = curve_->FirstParameter(), natLast = curve_->LastParameter();
    const double lo = std::min(first_, last_), hi = std::max(first_, last_);
    tMin_ = Precision::IsInfinite(natFirst) ? lo : std::min(natFirst, lo);
    tMax_ = Precision::IsInfinite(natLast) ? hi : std::max(natLast, hi);
    adaptor_ = new Geom2dAdaptor_Curve(curve_);
  } catch (const Standard_Failure& e) {
    throw MeshingError(name_ + ": OCCT could not load the pcurve: " + occtMessage(e));
  }
}

OcctCurve2d::OcctCurve2d(const OcctCurve2d& other)
    : ParametricCurve2d(other),
      curve_(other.curve_),
      first_(other.first_),
      last_(other.last_),
      tMin_(other.tMin_),
      tMax_(other.tMax_),
      name_(other.name_) {
  try {
    adaptor_ = new Geom2dAdaptor_Curve(curve_);  // a new cache over the shared geometry
  } catch (const Standard_Failure& e) {
    throw MeshingError(name_ + ": OCCT could not load the pcurve: " + occtMessage(e));
  }
}

std::unique_ptr<ParametricCurve2d> OcctCurve2d::clone() const {
  return std::unique_ptr<ParametricCurve2d>(new OcctCurve2d(*this));
}

void OcctCurve2d::fail(const char* what, double t, const std::string& occtMessage) const {
  std::ostringstream s;
  s.precision(17);
  s << name_ << ": OCCT failed to evaluate the pcurve's " << what << " at t = " << t << ": "
    << occtMessage;
  throw MeshingError(s.str());
}

Vec2 OcctCurve2d::point(double t) const {
  gp_Pnt2d p;
  try {
    adaptor_->D0(t, p);
  } catch (const Standard_Failure& e) {
    fail("point", t, occtMessage(e));
  }
  return {p.X(), p.Y()};
}

Curve2dD2 OcctCurve2d::d2(double t) const {
  gp_Pnt2d p;
  gp_Vec2d v1, v2;
  try {
    adaptor_->D2(t, p, v1, v2);
  } catch (const Standard_Failure& e) {
    fail("derivatives", t, occtMessage(e));
  }
  return {Vec2(p.X(), p.Y()), Vec2(v1.X(), v1.Y()), Vec2(v2.X(), v2.Y())};
}

}  // namespace aniso::cad
