// OcctSurface: ParametricSurface over an OCCT face's surface (see OcctSurface.h).
#include "cad/OcctSurface.h"

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Extrema_ExtAlgo.hxx>
#include <GeomAbs_SurfaceType.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

#include <cmath>
#include <limits>
#include <sstream>

#include "cad/detail/OcctConvert.h"
#include "mesher/core/Error.h"

namespace aniso::cad {
namespace {

using detail::occtMessage;
using detail::toEigen;

/// Fraction of a face's parametric extent added on each side of an unbounded direction.
constexpr double kUnboundedMargin = 0.1;
/// A projection is accepted as converged when the residual r = x − p(u,v) is normal to the
/// surface: |cos(r, p_u)| and |cos(r, p_v)| at most this (an angle of ~1e-5 rad).
constexpr double kStationaryCosine = 1e-5;
/// A residual below this fraction of the local surface scale counts as "on the surface".
constexpr double kOnSurface = 1e-9;

/// Replaces an infinite pair of natural bounds by the face's bounds widened by the margin.
void boundDirection(double& lo, double& hi, double faceLo, double faceHi) {
  if (!Precision::IsInfinite(lo) && !Precision::IsInfinite(hi)) return;
  const double extent = faceHi - faceLo;
  const double margin = kUnboundedMargin * (extent > 0 ? extent : 1.0);
  if (Precision::IsInfinite(lo)) lo = faceLo - margin;
  if (Precision::IsInfinite(hi)) hi = faceHi + margin;
}

/// The value t + k·period (k integer) nearest to ref.
double nearestPeriodic(double t, double ref, double period) {
  return period > 0 ? t + period * std::round((ref - t) / period) : t;
}

}  // namespace

OcctSurface::OcctSurface(const TopoDS_Face& face, std::string name) : name_(std::move(name)) {
  try {
    surface_ = BRep_Tool::Surface(face);  // a transformed copy when the face has a location
    if (surface_.IsNull()) throw MeshingError(name_ + ": the face has no surface");
    surface_->Bounds(domain_.u0, domain_.u1, domain_.v0, domain_.v1);
    const bool unbounded = Precision::IsInfinite(domain_.u0) || Precision::IsInfinite(domain_.u1) ||
                           Precision::IsInfinite(domain_.v0) || Precision::IsInfinite(domain_.v1);
    if (unbounded) {
      double fu0, fu1, fv0, fv1;
      BRepTools::UVBounds(face, fu0, fu1, fv0, fv1);
      if (Precision::IsInfinite(fu0) || Precision::IsInfinite(fu1) ||
          Precision::IsInfinite(fv0) || Precision::IsInfinite(fv1) || fu0 > fu1 || fv0 > fv1)
        throw MeshingError(name_ + ": unbounded surface and the face has no boundary");
      boundDirection(domain_.u0, domain_.u1, fu0, fu1);
      boundDirection(domain_.v0, domain_.v1, fv0, fv1);
    }
    domain_.uPeriodic = surface_->IsUPeriodic();
    domain_.vPeriodic = surface_->IsVPeriodic();
    if (domain_.uPeriodic) domain_.uPeriod = surface_->UPeriod();
    if (domain_.vPeriodic) domain_.vPeriod = surface_->VPeriod();
    adaptor_ = new GeomAdaptor_Surface(surface_);
  } catch (const Standard_Failure& e) {
    throw MeshingError(name_ + ": OCCT could not load the surface: " + occtMessage(e));
  }
}

OcctSurface::OcctSurface(const Handle(Geom_Surface)& surface, const SurfaceDomain& domain,
                         std::string name)
    : surface_(surface), domain_(domain), name_(std::move(name)) {
  try {
    adaptor_ = new GeomAdaptor_Surface(surface_);
  } catch (const Standard_Failure& e) {
    throw MeshingError(name_ + ": OCCT could not load the surface: " + occtMessage(e));
  }
}

bool OcctSurface::affine() const { return adaptor_->GetType() == GeomAbs_Plane; }

std::unique_ptr<ParametricSurface> OcctSurface::clone() const {
  // The Geom_ surface is immutable and shared; the adaptor (with its cache) is new.
  return std::unique_ptr<ParametricSurface>(new OcctSurface(surface_, domain_, name_));
}

void OcctSurface::fail(const char* what, const Vec2& uv, const char* occtMessage) const {
  std::ostringstream s;
  s.precision(17);
  s << name_ << ": OCCT failed to evaluate the " << what << " at (u,v) = (" << uv.x() << ", "
    << uv.y() << "): " << occtMessage;
  throw MeshingError(s.str());
}

Vec3 OcctSurface::point(const Vec2& uv) const {
  gp_Pnt p;
  try {
    adaptor_->D0(uv.x(), uv.y(), p);
  } catch (const Standard_Failure& e) {
    fail("point", uv, occtMessage(e).c_str());
  }
  return toEigen(p);
}

SurfaceD1 OcctSurface::d1(const Vec2& uv) const {
  gp_Pnt p;
  gp_Vec pu, pv;
  try {
    adaptor_->D1(uv.x(), uv.y(), p, pu, pv);
  } catch (const Standard_Failure& e) {
    fail("first derivatives", uv, occtMessage(e).c_str());
  }
  return {toEigen(p), toEigen(pu), toEigen(pv)};
}

SurfaceD2 OcctSurface::d2(const Vec2& uv) const {
  gp_Pnt p;
  gp_Vec pu, pv, puu, pvv, puv;
  try {
    adaptor_->D2(uv.x(), uv.y(), p, pu, pv, puu, pvv, puv);
  } catch (const Standard_Failure& e) {
    fail("second derivatives", uv, occtMessage(e).c_str());
  }
  return {toEigen(p), toEigen(pu), toEigen(pv), toEigen(puu), toEigen(puv), toEigen(pvv)};
}

bool OcctSurface::isLocalMinimum(const Vec3& x, const Vec2& uv) const {
  const SurfaceD2 d = d2(uv);
  const Vec3 r = x - d.p;
  const double scale = d.p.norm() + d.pu.norm() + d.pv.norm();
  const double rn = r.norm();
  if (rn <= kOnSurface * scale) return true;
  // First order: the gradient of ½|p − x|² vanishes in every free direction. A direction
  // is not free where p_i vanishes (a pole) or where the domain bound clamps the iteration
  // and the distance still decreases outwards.
  const Vec3* tangents[2] = {&d.pu, &d.pv};
  const bool periodic[2] = {domain_.uPeriodic, domain_.vPeriodic};
  const double lo[2] = {domain_.u0, domain_.v0}, hi[2] = {domain_.u1, domain_.v1};
  bool free[2] = {true, true};
  for (int i = 0; i < 2; ++i) {
    const double tn = tangents[i]->norm();
    if (tn <= kOnSurface * scale) continue;
    const double c = r.dot(*tangents[i]) / (rn * tn);
    if (std::abs(c) <= kStationaryCosine) continue;
    const double eps = 1e-12 * (std::abs(hi[i] - lo[i]) + std::abs(uv[i]));
    const bool clamped = !periodic[i] && ((c < 0 && uv[i] <= lo[i] + eps) ||
                                          (c > 0 && uv[i] >= hi[i] - eps));
    if (!clamped) return false;
    free[i] = false;
  }
  // Second order: the Hessian JᵀJ − r·p_ij is positive semi-definite on the free
  // directions (rejects the farthest point and saddles, where the gradient vanishes too).
  Mat2 h;
  h(0, 0) = d.pu.dot(d.pu) - r.dot(d.puu);
  h(0, 1) = h(1, 0) = d.pu.dot(d.pv) - r.dot(d.puv);
  h(1, 1) = d.pv.dot(d.pv) - r.dot(d.pvv);
  const double eps = kOnSurface * (d.pu.squaredNorm() + d.pv.squaredNorm() + rn * scale);
  if (free[0] && h(0, 0) < -eps) return false;
  if (free[1] && h(1, 1) < -eps) return false;
  if (free[0] && free[1] && h(0, 0) * h(1, 1) - h(0, 1) * h(0, 1) < -eps * eps) return false;
  return true;
}

std::optional<Vec2> OcctSurface::globalProject(const Vec3& x, const Vec2& start) const {
  GeomAPI_ProjectPointOnSurf proj;
  proj.Init(gp_Pnt(x.x(), x.y(), x.z()), surface_, domain_.u0, domain_.u1, domain_.v0,
            domain_.v1, Extrema_ExtAlgo_Grad);
  if (!proj.IsDone() || proj.NbPoints() == 0) return std::nullopt;
  std::optional<Vec2> best;
  double bestDist = 0, bestStartDist = 0;
  for (int i = 1; i <= proj.NbPoints(); ++i) {
    double u, v;
    proj.Parameters(i, u, v);
    const Vec2 uv(domain_.uPeriodic ? nearestPeriodic(u, start.x(), domain_.uPeriod) : u,
                  domain_.vPeriodic ? nearestPeriodic(v, start.y(), domain_.vPeriod) : v);
    const double dist = proj.Distance(i);
    const double startDist = (uv - start).norm();
    // Nearest in 3D; among (numerically) equally near ones, nearest to the start.
    const double tie = 1e-12 * (1.0 + dist);
    if (!best || dist < bestDist - tie || (dist <= bestDist + tie && startDist < bestStartDist)) {
      best = uv;
      bestDist = dist;
      bestStartDist = startDist;
    }
  }
  return best;
}

Vec2 OcctSurface::project(const Vec3& x, const Vec2& start) const {
  Vec2 uv = start;
  try {
    uv = ParametricSurface::project(x, start);
    if (isLocalMinimum(x, uv)) return uv;
  } catch (...) {
    // An evaluation failed during the iteration: the global search below decides.
  }
  try {
    const std::optional<Vec2> g = globalProject(x, start);
    if (!g) return uv;
    double local = std::numeric_limits<double>::infinity();
    try {
      local = (point(uv) - x).norm();
    } catch (const MeshingError&) {
    }
    if ((point(*g) - x).norm() < local) uv = *g;
  } catch (...) {
    // OCCT's search failed as well: keep the iteration's best point.
  }
  return uv;
}

}  // namespace aniso::cad
