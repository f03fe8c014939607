#include "mesher/control/CSOctree3d.h"

namespace aniso {

CSOctree3d::CSOctree3d(const Box3& bounds, const SizingParameters& params, const TreeLimits& limits)
    : cs_(bounds, params, limits) {}

void CSOctree3d::setContinuousSource(const ControlSpace3d& source) {
  cs_.setContinuous([&source](const Vec3& x) { return source.getMetric(x); });
  initializeControlVertices();  // folds in point / extended sources collected while fresh
}

}  // namespace aniso
