#include "mesher/control/CSAdaptive2d.h"

#include "mesher/control/CSAdaptiveGeneral.h"

namespace aniso {

void CSAdaptive2d::initializeControlVertices() {
  initializeVertexMetrics();
  auto pending = std::move(pendingExtended_);
  pendingExtended_.clear();
  for (const auto& [source, sizing] : pending) applyExtendedDomain(*source, sizing);
}

void CSAdaptive2d::superpose(const ControlSpace2d& other) {
  superposeAdaptive(*this, other, [](const ControlSpace2d& space, const Vec2& x) { return space.getMetric(x).sizing; });
}

void CSAdaptive2d::insertExtendedSource(const ExtendedSource2d& source, const Metric2d& sizing) {
  const Mat2 ms = sizing.matrix();
  const MetricLength2d length = [this, &ms](const Vec2& at, const Vec2& v) {
    return (ms * (parameterizationAt(at) * v)).norm();
  };
  for (const Vec2& p : source.samplePoints(length)) insertDiscreteSource(p, sizing);
  if (initialized())
    applyExtendedDomain(source, sizing);
  else
    pendingExtended_.emplace_back(source.clone(), sizing);
}

void CSAdaptive2d::applyExtendedDomain(const ExtendedSource2d& source, const Metric2d& sizing) {
  aniso::applyExtendedDomain(*this, source, sizing);
}

}  // namespace aniso
