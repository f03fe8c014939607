#pragma once
// CurveOnSurface3d — the 3D curve c = p∘c_p of a pcurve on a surface (eq. 2.44: "c is a
// superposition p∘c_p"), for analytic models whose edges are given in parametric space.
// Derivatives by the chain rule: c' = pu u' + pv v',
// c'' = puu u'² + 2 puv u'v' + pvv v'² + pu u'' + pv v''. Range: the pcurve's.
#include "mesher/geometry/ParametricCurve2d.h"
#include "mesher/geometry/ParametricCurve3d.h"
#include "mesher/geometry/ParametricSurface.h"

namespace aniso {

class CurveOnSurface3d final : public ParametricCurve3d {
 public:
  /// Throws InputError when either pointer is null.
  CurveOnSurface3d(SurfacePtr surface, Curve2dPtr pcurve);

  Vec3 point(double t) const override;
  Curve3dD2 d2(double t) const override;
  double tMin() const override;
  double tMax() const override;
  /// Deep copy: clones of the surface and of the pcurve (for use in another thread).
  std::unique_ptr<ParametricCurve3d> clone() const override;

  const SurfacePtr& surface() const { return surface_; }
  const Curve2dPtr& pcurve() const { return pcurve_; }

 private:
  SurfacePtr surface_;
  Curve2dPtr pcurve_;
};

}  // namespace aniso
