#include "mesher/metric/ContourCurvatureMetric.h"

#include <algorithm>

#include "mesher/metric/SurfaceMetric.h"

namespace aniso {

Metric2d contourCurvatureSizing(double kappa, const Vec2& tangentUV, const Mat2& mp,
                                const CurvatureSizing& sizing) {
  sizing.check();
  const double h1 = sizing.length(kappa);                                // eq. 2.46
  const double h2 = std::min(sizing.contourAnisotropy * h1, std::max(h1, sizing.hMax));
  const double alpha = angleInRealSpace(mp, tangentUV);
  return Metric2d::fromAngle(alpha, h1, h2);
}

Metric2d contourCurvatureSizing(const ParametricCurve2d& curve, double t,
                                const ParametricSurface& surface, double gMin,
                                const CurvatureSizing& sizing) {
  const Curve2dD2 d = curve.d2(t);
  return contourCurvatureSizing(curve.curvature(t, surface), d.d1,
                                surface.parameterizationTensor(d.p, gMin), sizing);
}

}  // namespace aniso
