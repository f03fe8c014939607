#include "mesher/sizing/PointSizing.h"

#include <cmath>
#include <limits>

namespace aniso {

void insertFacePoints(CSAdaptive2d& cs, const std::vector<SizingPoint>& points, const ParametricSurface& surface,
                      const Box2& bounds, double gMin) {
  if (points.empty()) return;
  const int n = kPointSampleGrid;
  std::vector<Vec2> uvs;
  std::vector<Vec3> xyz;
  Box3 faceBox;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const Vec2 uv = bounds.lo + Vec2(double(i) / n, double(j) / n).cwiseProduct(bounds.size());
      uvs.push_back(uv);
      xyz.push_back(surface.point(uv));
      faceBox.add(xyz.back());
    }
  // the sample misses bulges between its points: a box grown by a sample spacing
  const double grow = faceBox.diagonal() / n;
  const double uvTol = 1e-9 * std::max(bounds.diagonal(), 1e-300);
  for (const SizingPoint& p : points) {
    const double h = p.metric.axes().lengths.minCoeff();
    const double near = kPointOnFaceFraction * h;
    if (!faceBox.contains(p.at, grow + near)) continue;
    std::size_t best = 0;
    double bestD = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < xyz.size(); ++k) {
      const double d = (xyz[k] - p.at).squaredNorm();
      if (d < bestD) bestD = d, best = k;
    }
    const Vec2 uv = surface.project(p.at, uvs[best]);
    if (!uv.allFinite() || !bounds.contains(uv, uvTol)) continue;
    if ((surface.point(uv) - p.at).norm() > near) continue;
    const SurfaceD1 d = surface.d1(uv);
    const Metric2d m = restrictToSurface(p.metric, d.pu, d.pv, surface.parameterizationTensor(uv, gMin));
    cs.insertDiscreteSource(uv, m);
  }
}

void insertSolidPoints(CSAdaptive3d& cs, const std::vector<SizingPoint>& points, const Box3& box) {
  for (const SizingPoint& p : points)
    if (box.contains(p.at)) cs.insertDiscreteSource(p.at, p.metric);
}

}  // namespace aniso
