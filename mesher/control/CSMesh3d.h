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
// The operations shared with CSMesh2d are in CSMesh<D> (CSMesh.h).
// For repeated queries at nearby points wrap calls in a MetricQueryCache3d.
// Thread safety: getMetric() and the other const methods may run concurrently on a
// control space that is not being modified (per-thread location hints, PerThreadState).
#include "mesher/control/CSMesh.h"

namespace aniso {

class CSMesh3d final : public CSMesh<3> {
 public:
  /// Throws InputError for an empty box or bad parameters / options.
  CSMesh3d(const Box3& bounds, const SizingParameters& params, const BackgroundMeshOptions& options = {})
      : CSMesh<3>(bounds, params, options) {}

  // ControlSpace3d
  Metric3d getMetric(const Vec3& x) const override { return mesh_.metricAt(x, hints_.local()); }

  // CSAdaptive3d
  void setContinuousSource(const ControlSpace3d& source) override;

  // background-mesh specifics
  /// getMetric with a caller-owned location hint (one per thread).
  Metric3d getMetric(const Vec3& x, MeshLocateHint3d& hint) const { return mesh_.metricAt(x, hint); }
  std::size_t tetCount() const { return mesh_.tetMesh().numTets(); }
};

}  // namespace aniso
