#include "mesher/control/CSAdaptive3d.h"

#include "mesher/metric/MetricIntersection.h"

namespace aniso {

void CSAdaptive3d::initializeControlVertices() {
  initializeVertexMetrics();
  auto pending = std::move(pendingExtended_);
  pendingExtended_.clear();
  for (const auto& [source, sizing] : pending) applyExtendedDomain(*source, sizing);
}

void CSAdaptive3d::superpose(const ControlSpace3d& other) {
  if (&other == this) return;  // min_M(A, A) = A
  const auto* adaptive = dynamic_cast<const CSAdaptive3d*>(&other);
  if (!initialized() || !adaptive) {
    setContinuousSource(other);
    if (!adaptive) return;
  }
  const auto intersectWithOther = [&other](const Vec3& x, Metric3d& m) { return intersectInto(m, other.getMetric(x)); };
  modifyControlVertices(intersectWithOther);                                                         // (1)
  adaptive->forEachControlVertex([this](const Vec3& x, const Metric3d& m) { insertDiscreteSource(x, m); });  // (2)
  modifyControlVertices(intersectWithOther);                                                         // (3)
}

void CSAdaptive3d::insertExtendedSource(const ExtendedSource3d& source, const Metric3d& sizing) {
  for (const Vec3& p : source.samplePoints(sizing)) insertDiscreteSource(p, sizing);
  if (initialized())
    applyExtendedDomain(source, sizing);
  else
    pendingExtended_.emplace_back(source.clone(), sizing);
}

void CSAdaptive3d::applyExtendedDomain(const ExtendedSource3d& source, const Metric3d& sizing) {
  const Box3 box = source.bounds();
  modifyControlVertices([&](const Vec3& x, Metric3d& m) {
    return box.contains(x, 1e-12 * (1 + box.diagonal())) && source.contains(x) && intersectInto(m, sizing);
  });
}

}  // namespace aniso
