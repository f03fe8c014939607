// OcctCurve3d: ParametricCurve3d over an OCCT edge's 3D geometry (see OcctCurve3d.h).
#include "cad/OcctCurve3d.h"

#include <Adaptor3d_CurveOnSurface.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TopLoc_Location.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <sstream>

#include "mesher/core/Error.h"

namespace aniso::cad {
namespace {

std::string occtMessage(const Standard_Failure& e) {
  const char* m = e.GetMessageString();
  return (m && *m) ? std::string(m) : std::string(e.DynamicType()->Name());
}

Vec3 toVec(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Vec3 toVec(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

}  // namespace

OcctCurve3d::OcctCurve3d(const TopoDS_Edge& edge, std::string name) : name_(std::move(name)) {
  try {
    if (BRep_Tool::Degenerated(edge))
      throw MeshingError(name_ + ": a degenerate edge has no 3D curve");
    double natFirst = 0, natLast = 0;
    curve_ = BRep_Tool::Curve(edge, first_, last_);  // a transformed copy under a location
    if (!curve_.IsNull()) {
      natFirst = curve_->FirstParameter();
      natLast = curve_->LastParameter();
    } else {
      TopLoc_Location loc;
      BRep_Tool::CurveOnSurface(edge, pcurve_, surface_, loc, first_, last_, 1);
      if (pcurve_.IsNull() || surface_.IsNull())
        throw MeshingError(name_ + ": the edge has neither a 3D curve nor a pcurve");
      if (!loc.IsIdentity())
        surface_ = Handle(Geom_Surface)::DownCast(surface_->Transformed(loc.Transformation()));
      natFirst = pcurve_->FirstParameter();
      natLast = pcurve_->LastParameter();
    }
    const double lo = std::min(first_, last_), hi = std::max(first_, last_);
    tMin_ = Precision::IsInfinite(natFirst) ? lo : std::min(natFirst, lo);
    tMax_ = Precision::IsInfinite(natLast) ? hi : std::max(natLast, hi);
    makeAdaptor();
  } catch (const Standard_Failure& e) {
    throw MeshingError(name_ + ": OCCT could not load the curve: " + occtMessage(e));
  }
}

OcctCurve3d::OcctCurve3d(const OcctCurve3d& other)
    : ParametricCurve3d(other),
      curve_(other.curve_),
      pcurve_(other.pcurve_),
      surface_(other.surface_),
      first_(other.first_),
      last_(other.last_),
      tMin_(other.tMin_),
      tMax_(other.tMax_),
      name_(other.name_) {
  try {
    makeAdaptor();  // new caches over the shared immutable geometry
  } catch (const Standard_Failure& e) {
    throw MeshingError(name_ + ": OCCT could not load the curve: " + occtMessage(e));
  }
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

void OcctCurve3d::fail(const char* what, double t, const std::string& occtMessage) const {
  std::ostringstream s;
  s.precision(17);
  s << name_ << ": OCCT failed to evaluate the curve's " << what << " at t = " << t << ": "
    << occtMessage;
  throw MeshingError(s.str());
}

Vec3 OcctCurve3d::point(double t) const {
  gp_Pnt p;
  try {
    adaptor_->D0(t, p);
  } catch (const Standard_Failure& e) {
    fail("point", t, occtMessage(e));
  }
  return toVec(p);
}

Curve3dD2 OcctCurve3d::d2(double t) const {
  gp_Pnt p;
  gp_Vec v1, v2;
  try {
    adaptor_->D2(t, p, v1, v2);
  } catch (const Standard_Failure& e) {
    fail("derivatives", t, occtMessage(e));
  }
  return {toVec(p), toVec(v1), toVec(v2)};
}

}  // namespace aniso::cad
