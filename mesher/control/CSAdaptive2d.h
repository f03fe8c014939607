#pragma once
// CSAdaptive2d — the adaptive control space (ACS) interface for surface meshing (sec. 3.2,
// 3.2.1, 6.3.1, fig. 6.4), implemented by CSQuadtree2d (and later the background mesh).
//
// Elementary operations (virtual, sec. 3.2.1):
//   insertDiscreteSource      a point source (u, v, M_s). Before the control vertices
//                             carry metrics it is collected ("setting initial control
//                             space", 3.3.1); afterwards it adapts the structure and
//                             intersects the metric near the point ("updating control
//                             space", 3.3.1);
//   setContinuousSource       metric from another control space over the whole domain
//                             (3.3.2), intersected with the existing one; point and
//                             extended sources collected before are then folded in
//                             (initializeControlVertices);
//   initializeControlVertices control vertices from the collected point sources, with
//                             extrapolation (3.3.1 steps 2–3);
//   adaptToParameterization   refine until M_p is nearly constant per control element and
//                             cache M_p at the control vertices (3.3.3, 3.2.4 item 1);
//   smoothGradation           global gradation control with ratio γ_M (3.3.4);
//   forEachControlVertex / modifyControlVertices   iterate the control vertices.
// General-level operations (implemented here on top of the above):
//   superpose                 superposition with another control space (3.2.3);
//   insertExtendedSource      an extended metric source (3.2.2).
// Metrics are sizing components M_s acting on S^R (SurfaceMetric.h); points are (u, v).
// Thread safety: getMetric() and the const queries may run concurrently; every other
// operation needs exclusive access.
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/control/ExtendedSource2d.h"
#include "mesher/geometry/ParametricSurface.h"

namespace aniso {

class CSAdaptive2d : public ControlSpace2d {
 public:
  using VertexVisitor = std::function<void(const Vec2& uv, const Metric2d& sizing)>;
  /// Returns whether it changed the metric.
  using VertexModifier = std::function<bool(const Vec2& uv, Metric2d& sizing)>;

  // ---- elementary operations ----
  virtual void insertDiscreteSource(const Vec2& uv, const Metric2d& sizing) = 0;
  /// Uses source.getMetric(uv).sizing.
  virtual void setContinuousSource(const ControlSpace2d& source) = 0;
  /// Initializes the control vertices from the collected point sources and then applies
  /// the domains of extended sources inserted before (see insertExtendedSource). Throws
  /// MeshingError when there is no metric at all. No-op when already initialized and
  /// nothing is pending.
  void initializeControlVertices();
  /// True when every control vertex carries a metric (getMetric() works).
  virtual bool initialized() const = 0;
  /// Point sources collected and not yet used by initializeControlVertices().
  virtual std::size_t pendingSourceCount() const = 0;
  /// gMin: the guard of ParametricSurface::parameterizationTensor (model units²). The
  /// surface is cloned; afterwards getMetric() returns the cached, interpolated M_p.
  virtual void adaptToParameterization(const ParametricSurface& surface, double gMin) = 0;
  /// The cached M_p at uv (identity before adaptToParameterization).
  virtual Mat2 parameterizationAt(const Vec2& uv) const = 0;
  /// Returns the number of sweeps. Throws MeshingError when not initialized.
  virtual int smoothGradation(double gamma) = 0;
  /// Visits the control vertices (none before initialization).
  virtual void forEachControlVertex(const VertexVisitor& visit) const = 0;
  virtual void modifyControlVertices(const VertexModifier& modify) = 0;
  virtual std::size_t controlVertexCount() const = 0;

  // ---- general level ----
  /// Sec. 3.2.3: with an adaptive `other` — (1) every control vertex V ← min_M(M_V,
  /// other(V)); (2) every control vertex of `other` is inserted as a point source; (3) as
  /// (1). With a non-adaptive `other`: setContinuousSource(other). A control space that
  /// is not initialized yet is first initialized from `other` (setContinuousSource).
  void superpose(const ControlSpace2d& other);
  /// Sec. 3.2.2: the skeleton and outline points of `source`, at unit distance in the
  /// metric M_s M_p, are inserted as point sources (adapting the structure); then every
  /// control vertex inside the source's domain gets M_V ← min_M(M_V, M_s). Before
  /// initialization the second step is deferred to initializeControlVertices().
  void insertExtendedSource(const ExtendedSource2d& source, const Metric2d& sizing);

 protected:
  /// The implementation of initializeControlVertices() (steps 2–3 of 3.3.1).
  virtual void initializeVertexMetrics() = 0;

 private:
  void applyExtendedDomain(const ExtendedSource2d& source, const Metric2d& sizing);
  std::vector<std::pair<std::unique_ptr<ExtendedSource2d>, Metric2d>> pendingExtended_;
};

}  // namespace aniso
