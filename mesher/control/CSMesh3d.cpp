#include "mesher/control/CSMesh3d.h"

namespace aniso {

CSMesh3d::CSMesh3d(const Box3& bounds, const SizingParameters& params, const BackgroundMeshOptions& options)
    : mesh_(bounds, params, options), hints_([] { return std::make_unique<MeshLocateHint3d>(); }) {}

void CSMesh3d::setContinuousSource(const ControlSpace3d& source) {
  mesh_.setContinuous([&source](const Vec3& x) { return source.getMetric(x); });
  initializeControlVertices();  // folds in point / extended sources collected while fresh
}

}  // namespace aniso
