#include "mesher/control/CSAdaptive2d.h"

#include "mesher/metric/MetricIntersection.h"

namespace aniso {

void CSAdaptive2d::initializeControlVertices() {
  initializeVertexMetrics();
  auto pending = std::move(pendingExtended_);
  pendingExtended_.clear();
  for (const auto& [source, sizing] : pending) applyExtendedDomain(*source, sizing);
}

void CSAdaptive2d::superpose(const ControlSpace2d& other) {
  if (&other == this) return;  // min_M(A, A) = A
  const auto* adaptive = dynamic_cast<const CSAdaptive2d*>(&other);
  if (!initialized() || !adaptive) {
    setContinuousSource(other);
    if (!adaptive) return;
  }
  const auto intersectWithOther = [&other](const Vec2& uv, Metric2d& m) {
    return intersectInto(m, other.getMetric(uv).sizing);
  };
  modifyControlVertices(intersectWithOther);                                                     // (1)
  adaptive->forEachControlVertex([this](const Vec2& uv, const Metric2d& m) { insertDiscreteSource(uv, m); });  // (2)
  modifyControlVertices(intersectWithOther);                                                     // (3)
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
  const Box2 box = source.bounds();
  modifyControlVertices([&](const Vec2& uv, Metric2d& m) {
    return box.contains(uv, 1e-12 * (1 + box.diagonal())) && source.contains(uv) && intersectInto(m, sizing);
  });
}

}  // namespace aniso
