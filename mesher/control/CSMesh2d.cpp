#include "mesher/control/CSMesh2d.h"

#include <cmath>
#include <string>

#include "mesher/core/Error.h"

namespace aniso {

SurfaceMetricAt CSMesh2d::getMetric(const Vec2& uv) const { return getMetric(uv, hints_.local()); }

SurfaceMetricAt CSMesh2d::getMetric(const Vec2& uv, MeshLocateHint2d& hint) const {
  SurfaceMetricAt r;
  mesh_.sample(uv, hint, r.sizing, r.parameterization);
  return r;
}

void CSMesh2d::setContinuousSource(const ControlSpace2d& source) {
  mesh_.setContinuous([&source](const Vec2& uv) { return source.getMetric(uv).sizing; });
  initializeControlVertices();  // folds in point / extended sources collected while fresh
}

void CSMesh2d::adaptToParameterization(const ParametricSurface& surface, double gMin) {
  if (!(std::isfinite(gMin) && gMin >= 0))
    throw InputError("background mesh control space: gMin = " + std::to_string(gMin) + " must be finite and >= 0");
  surface_ = surface.clone();
  const ParametricSurface* s = surface_.get();
  mesh_.adaptAux([s, gMin](const Vec2& uv) { return s->parameterizationTensor(uv, gMin); });
}

}  // namespace aniso
