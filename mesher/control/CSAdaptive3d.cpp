#include "mesher/control/CSAdaptive3d.h"

#include "mesher/control/CSAdaptiveGeneral.h"

namespace aniso {

void CSAdaptive3d::initializeControlVertices() {
  initializeVertexMetrics();
  auto pending = std::move(pendingExtended_);
  pendingExtended_.clear();
  for (const auto& [source, sizing] : pending) applyExtendedDomain(*source, sizing);
}

void CSAdaptive3d::superpose(const ControlSpace3d& other) {
  superposeAdaptive(*this, other, [](const ControlSpace3d& space, const Vec3& x) { return space.getMetric(x); });
}

void CSAdaptive3d::insertExtendedSource(const ExtendedSource3d& source, const Metric3d& sizing) {
  for (const Vec3& p : source.samplePoints(sizing)) insertDiscreteSource(p, sizing);
  if (initialized())
    applyExtendedDomain(source, sizing);
  else
    pendingExtended_.emplace_back(source.clone(), sizing);
}

void CSAdaptive3d::applyExtendedDomain(const ExtendedSource3d& source, const Metric3d& sizing) {
  aniso::applyExtendedDomain(*this, source, sizing);
}

}  // namespace aniso
