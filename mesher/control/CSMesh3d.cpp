#include "mesher/control/CSMesh3d.h"

namespace aniso {

void CSMesh3d::setContinuousSource(const ControlSpace3d& source) {
  mesh_.setContinuous([&source](const Vec3& x) { return source.getMetric(x); });
  initializeControlVertices();  // folds in point / extended sources collected while fresh
}

}  // namespace aniso
