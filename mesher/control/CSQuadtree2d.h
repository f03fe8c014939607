#pragma once
// CSQuadtree2d — the balanced-quadtree adaptive control space for surface meshing
// (sec. 3.3, fig. 3.1, 6.3.1) over a rectangle of the parametric plane.
//
// Structure and field: TreeControlSpace<2> (see TreeControlSpace.h for the interpolation,
// the hanging-vertex handling and the procedures) on a BalancedTree<2> (flat, index-based,
// 2:1 balanced across edges and corners). getMetric() locates the leaf by direct descent
// (O(depth)) and interpolates the length tensors of its vertices (eq. 3.1 / 2.18) and,
// after adaptToParameterization(), the cached M_p (sec. 3.2.4 item 1).
// Split rules (3.3.1) use ε_M, l_Mmax and ε_δ of the SizingParameters given at
// construction; TreeLimits bounds the depth and the resolution of the continuous and
// parameterization adaptations.
// For repeated queries at nearby points wrap calls in a MetricQueryCache2d (the proximity
// check of sec. 3.2.4 item 3).
// Thread safety: getMetric(), parameterizationAt() and the other const methods may run
// concurrently on a control space that is not being modified.
#include <memory>

#include "mesher/control/CSAdaptive2d.h"
#include "mesher/control/ControlSpaceGrid.h"
#include "mesher/control/TreeControlSpace.h"
#include "mesher/core/MeshOptions.h"

namespace aniso {

class CSQuadtree2d final : public CSAdaptive2d {
 public:
  /// Root cells over `bounds` (near-square). Throws InputError for an empty box or bad
  /// parameters.
  CSQuadtree2d(const Box2& bounds, const SizingParameters& params, const TreeLimits& limits = {});

  // ControlSpace2d
  SurfaceMetricAt getMetric(const Vec2& uv) const override;
  Box2 bounds() const override;
  std::uint64_t revision() const override { return cs_.revision(); }

  // CSAdaptive2d
  void insertDiscreteSource(const Vec2& uv, const Metric2d& sizing) override;
  void setContinuousSource(const ControlSpace2d& source) override;
  bool initialized() const override { return cs_.valued(); }
  std::size_t pendingSourceCount() const override { return cs_.pendingSources(); }
  void adaptToParameterization(const ParametricSurface& surface, double gMin) override;
  Mat2 parameterizationAt(const Vec2& uv) const override { return cs_.auxAt(uv); }
  int smoothGradation(double gamma) override { return cs_.smoothGradation(gamma); }
  void forEachControlVertex(const VertexVisitor& visit) const override { cs_.forEachVertex(visit); }
  void modifyControlVertices(const VertexModifier& modify) override { cs_.modifyVertices(modify); }
  std::size_t controlVertexCount() const override { return cs_.tree().vertexCount(); }

  // quadtree specifics
  /// The structure and field (tree(), edges(), vertexMetric(), ...), for inspection.
  const TreeControlSpace<2>& structure() const { return cs_; }
  std::size_t leafCount() const { return cs_.tree().leafCount(); }
  int depth() const { return cs_.tree().depth(); }
  /// Leaves and per-vertex tensors for visualisation.
  ControlSpaceGrid grid() const { return cs_.grid(); }
  /// Throws MeshingError naming the first broken invariant (TreeControlSpace::validate).
  void validate() const { cs_.validate(); }

 protected:
  void initializeVertexMetrics() override { cs_.initializeVertices(); }

 private:
  TreeControlSpace<2> cs_;
  std::unique_ptr<ParametricSurface> surface_;  ///< clone for M_p at new vertices
};

}  // namespace aniso
