#include "mesher/control/CSQuadtree2d.h"

#include <cmath>
#include <string>

#include "mesher/core/Error.h"

namespace aniso {

CSQuadtree2d::CSQuadtree2d(const Box2& bounds, const SizingParameters& params, const TreeLimits& limits)
    : cs_(bounds, params, limits) {}

SurfaceMetricAt CSQuadtree2d::getMetric(const Vec2& uv) const {
  SurfaceMetricAt r;
  cs_.sample(uv, r.sizing, r.parameterization);
  return r;
}

Box2 CSQuadtree2d::bounds() const { return cs_.tree().box(); }

void CSQuadtree2d::insertDiscreteSource(const Vec2& uv, const Metric2d& sizing) { cs_.insertDiscrete(uv, sizing); }

void CSQuadtree2d::setContinuousSource(const ControlSpace2d& source) {
  cs_.setContinuous([&source](const Vec2& uv) { return source.getMetric(uv).sizing; });
  initializeControlVertices();  // folds in point / extended sources collected while fresh
}

void CSQuadtree2d::adaptToParameterization(const ParametricSurface& surface, double gMin) {
  if (!(std::isfinite(gMin) && gMin >= 0))
    throw InputError("quadtree control space: gMin = " + std::to_string(gMin) + " must be finite and >= 0");
  surface_ = surface.clone();
  const ParametricSurface* s = surface_.get();
  cs_.adaptAux([s, gMin](const Vec2& uv) { return s->parameterizationTensor(uv, gMin); });
}

}  // namespace aniso
