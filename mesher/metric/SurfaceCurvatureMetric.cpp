#include "mesher/metric/SurfaceCurvatureMetric.h"

#include "mesher/metric/AnisotropyLimit.h"
#include "mesher/metric/SurfaceMetric.h"

namespace aniso {

Metric2d surfaceCurvatureSizing(const PrincipalCurvatures& pc, const Mat2& mp,
                                const CurvatureSizing& sizing) {
  sizing.check();
  return principalSizing(pc, mp, Vec2(sizing.length(pc.k1), sizing.length(pc.k2)), sizing.anisotropy);  // eq. 2.41
}

Metric2d principalSizing(const PrincipalCurvatures& pc, const Mat2& mp, Vec2 h, double anisotropy) {
  limitLengthRatio<2>(h, anisotropy);              // eq. 2.42
  const double alpha = angleInRealSpace(mp, pc.dir1);
  return Metric2d::fromAngle(alpha, h(0), h(1));   // eq. 2.4
}

Metric2d surfaceCurvatureSizing(const ParametricSurface& surface, const Vec2& uv, double gMin,
                                const CurvatureSizing& sizing) {
  return surfaceCurvatureSizing(surface.curvature(uv), surface.parameterizationTensor(uv, gMin), sizing);
}

}  // namespace aniso
