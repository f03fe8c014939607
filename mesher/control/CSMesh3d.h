#pragma once
// CSMesh3d — the background-mesh adaptive control space for volume meshing (thesis
// sec. 3.4, 6.3.2) over a bounding box: control vertices with metrics in the nodes of a
// Delaunay tetrahedralization (identity metric) of the control vertices. The sibling of
// CSOctree3d: same SizingParameters (ε_M, ε_δ, l_Mmax), same CSAdaptive3d operations,
// same grid() export (VTK_TETRA cells).
//
// Structure and field: BackgroundMesh3d (interpolation sets A_s / A_t / A_o over
// tetrahedra with the inverse squared-distance weights of eq. 3.2, the ε_M shortcut, the
// 8 corners of the kernel's enclosing box as control vertices). The procedures are those
// of CSMesh2d (see CSMesh2d.h: fresh and updating point sources with proximity merge and
// rings, continuous sources from a regular grid refined at circumcentres, smoothing by
// edge marking) without the parameterization.
// For repeated queries at nearby points wrap calls in a MetricQueryCache3d.
// Thread safety: getMetric() and the other const methods may run concurrently on a
// control space that is not being modified (per-thread location hints, PerThreadState).
#include "mesher/control/BackgroundMesh.h"
#include "mesher/control/CSAdaptive3d.h"
#include "mesher/control/ControlSpaceGrid.h"
#include "mesher/control/PerThreadState.h"
#include "mesher/core/MeshOptions.h"

namespace aniso {

class CSMesh3d final : public CSAdaptive3d {
 public:
  /// Throws InputError for an empty box or bad parameters / options.
  CSMesh3d(const Box3& bounds, const SizingParameters& params, const BackgroundMeshOptions& options = {});

  // ControlSpace3d
  Metric3d getMetric(const Vec3& x) const override { return mesh_.metricAt(x, hints_.local()); }
  Box3 bounds() const override { return mesh_.bounds(); }
  std::uint64_t revision() const override { return mesh_.revision(); }

  // CSAdaptive3d
  void insertDiscreteSource(const Vec3& x, const Metric3d& sizing) override { mesh_.insertDiscrete(x, sizing); }
  void setContinuousSource(const ControlSpace3d& source) override;
  bool initialized() const override { return mesh_.valued(); }
  std::size_t pendingSourceCount() const override { return mesh_.pendingSources(); }
  int smoothGradation(double gamma) override { return mesh_.smoothGradation(gamma); }
  void forEachControlVertex(const VertexVisitor& visit) const override { mesh_.forEachVertex(visit); }
  void modifyControlVertices(const VertexModifier& modify) override { mesh_.modifyVertices(modify); }
  /// Every vertex of the background mesh, the 8 box corners included.
  std::size_t controlVertexCount() const override { return mesh_.vertexCount(); }

  // background-mesh specifics
  /// getMetric with a caller-owned location hint (one per thread).
  Metric3d getMetric(const Vec3& x, MeshLocateHint3d& hint) const { return mesh_.metricAt(x, hint); }
  const BackgroundMesh3d& structure() const { return mesh_; }
  std::size_t tetCount() const { return mesh_.tetMesh().numTets(); }
  BackgroundInterpolation interpolation() const { return mesh_.options().interpolation; }
  void setInterpolation(BackgroundInterpolation method) { mesh_.setInterpolation(method); }
  /// Tetrahedra and per-vertex tensors for visualisation (cellSize 4, dim 3: VTK_TETRA).
  ControlSpaceGrid grid() const { return mesh_.grid(); }
  void validate() const { mesh_.validate(); }

 protected:
  void initializeVertexMetrics() override { mesh_.initializeVertices(); }

 private:
  BackgroundMesh3d mesh_;
  PerThreadState<MeshLocateHint3d> hints_;
};

}  // namespace aniso
