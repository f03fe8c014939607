#pragma once
// CSOctree3d — the balanced-octree adaptive control space for volume meshing (sec. 3.3,
// 6.3.2) over a bounding box.
//
// Structure and field: TreeControlSpace<3> (see TreeControlSpace.h for the trilinear
// interpolation of eq. 3.1, the hanging-vertex handling and the procedures) on a
// BalancedTree<3> (flat, index-based, 2:1 balanced across faces, edges and corners).
// getMetric() locates the leaf by direct descent (O(depth)).
// Split rules (3.3.1) use ε_M, l_Mmax and ε_δ of the SizingParameters given at
// construction; TreeLimits bounds the depth and the resolution of continuous adaptation.
// For repeated queries at nearby points wrap calls in a MetricQueryCache3d (sec. 3.2.4
// item 3).
// Thread safety: getMetric() and the other const methods may run concurrently on a
// control space that is not being modified.
#include "mesher/control/CSAdaptive3d.h"
#include "mesher/control/ControlSpaceGrid.h"
#include "mesher/control/TreeControlSpace.h"
#include "mesher/core/MeshOptions.h"

namespace aniso {

class CSOctree3d final : public CSAdaptive3d {
 public:
  /// Root cells over `bounds` (near-cubic). Throws InputError for an empty box or bad
  /// parameters.
  CSOctree3d(const Box3& bounds, const SizingParameters& params, const TreeLimits& limits = {});

  // ControlSpace3d
  Metric3d getMetric(const Vec3& x) const override { return cs_.metricAt(x); }
  Box3 bounds() const override { return cs_.tree().box(); }
  std::uint64_t revision() const override { return cs_.revision(); }

  // CSAdaptive3d
  void insertDiscreteSource(const Vec3& x, const Metric3d& sizing) override { cs_.insertDiscrete(x, sizing); }
  void setContinuousSource(const ControlSpace3d& source) override;
  bool initialized() const override { return cs_.valued(); }
  std::size_t pendingSourceCount() const override { return cs_.pendingSources(); }
  int smoothGradation(double gamma) override { return cs_.smoothGradation(gamma); }
  void forEachControlVertex(const VertexVisitor& visit) const override { cs_.forEachVertex(visit); }
  void modifyControlVertices(const VertexModifier& modify) override { cs_.modifyVertices(modify); }
  std::size_t controlVertexCount() const override { return cs_.tree().vertexCount(); }

  // octree specifics
  const TreeControlSpace<3>& structure() const { return cs_; }
  std::size_t leafCount() const { return cs_.tree().leafCount(); }
  int depth() const { return cs_.tree().depth(); }
  ControlSpaceGrid grid() const { return cs_.grid(); }
  void validate() const { cs_.validate(); }

 protected:
  void initializeVertexMetrics() override { cs_.initializeVertices(); }

 private:
  TreeControlSpace<3> cs_;
};

}  // namespace aniso
