#include "mesher/geometry/CurveOnSurface3d.h"

#include <utility>

#include "mesher/core/Error.h"

namespace aniso {

CurveOnSurface3d::CurveOnSurface3d(SurfacePtr surface, Curve2dPtr pcurve)
    : surface_(std::move(surface)), pcurve_(std::move(pcurve)) {
  if (!surface_ || !pcurve_) throw InputError("curve on surface: null surface or pcurve");
}

Vec3 CurveOnSurface3d::point(double t) const { return surface_->point(pcurve_->point(t)); }

Curve3dD2 CurveOnSurface3d::d2(double t) const {
  const Curve2dD2 c = pcurve_->d2(t);
  const SurfaceD2 s = surface_->d2(c.p);
  const double du = c.d1.x(), dv = c.d1.y();
  return {s.p, s.pu * du + s.pv * dv,
          s.puu * du * du + 2 * s.puv * du * dv + s.pvv * dv * dv + s.pu * c.d2.x() + s.pv * c.d2.y()};
}

double CurveOnSurface3d::tMin() const { return pcurve_->tMin(); }
double CurveOnSurface3d::tMax() const { return pcurve_->tMax(); }

std::unique_ptr<ParametricCurve3d> CurveOnSurface3d::clone() const {
  return std::make_unique<CurveOnSurface3d>(SurfacePtr(surface_->clone()), Curve2dPtr(pcurve_->clone()));
}

}  // namespace aniso
