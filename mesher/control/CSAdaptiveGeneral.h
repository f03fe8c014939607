#pragma once
// The general-level operations of the adaptive control spaces (sec. 3.2.2, 3.2.3), written
// once on top of the elementary ones for CSAdaptive2d and CSAdaptive3d (their members
// superpose and insertExtendedSource call these). Only public elementary operations are
// used; the caller keeps its own deferred extended sources.
//   superposeAdaptive(self, other, sizingOf)  sec. 3.2.3 (see CSAdaptive2d::superpose);
//                                             sizingOf(other, x) is other's M_s at x;
//   applyExtendedDomain(self, source, sizing) every control vertex of self inside the
//                                             source's domain gets M_V ← min_M(M_V, M_s).
#include "mesher/metric/MetricIntersection.h"

namespace aniso {

template <class Adaptive, class Space, class SizingOf>
void superposeAdaptive(Adaptive& self, const Space& other, SizingOf sizingOf) {
  if (&other == static_cast<const Space*>(&self)) return;  // min_M(A, A) = A
  const auto* adaptive = dynamic_cast<const Adaptive*>(&other);
  if (!self.initialized() || !adaptive) {
    self.setContinuousSource(other);
    if (!adaptive) return;
  }
  const auto intersectWithOther = [&other, &sizingOf](const auto& x, auto& m) {
    return intersectInto(m, sizingOf(other, x));
  };
  self.modifyControlVertices(intersectWithOther);                                                      // (1)
  adaptive->forEachControlVertex([&self](const auto& x, const auto& m) { self.insertDiscreteSource(x, m); });  // (2)
  self.modifyControlVertices(intersectWithOther);                                                      // (3)
}

template <class Adaptive, class Source, class MetricT>
void applyExtendedDomain(Adaptive& self, const Source& source, const MetricT& sizing) {
  const auto box = source.bounds();
  self.modifyControlVertices([&](const auto& x, MetricT& m) {
    return box.contains(x, 1e-12 * (1 + box.diagonal())) && source.contains(x) && intersectInto(m, sizing);
  });
}

}  // namespace aniso
