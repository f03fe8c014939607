#pragma once
// CSMesh<D> — what the background-mesh adaptive control spaces CSMesh2d (surface, sec.
// 3.4, 6.3.1) and CSMesh3d (volume, 6.3.2) share: the elementary operations of
// CSAdaptive2d / CSAdaptive3d forwarded to a BackgroundMesh<D> (see BackgroundMesh.h for
// the structure, the field and the procedures), its inspection, and the per-thread
// location hints of getMetric(). CSMesh2d and CSMesh3d add what differs: getMetric()
// (a SurfaceMetricAt with M_p / a Metric3d), setContinuousSource() and, in 2D, the
// parameterization.
// Thread safety: the const methods may run concurrently on a control space that is not
// being modified (per-thread location hints, PerThreadState).
#include <memory>
#include <type_traits>

#include "mesher/control/BackgroundMesh.h"
#include "mesher/control/CSAdaptive2d.h"
#include "mesher/control/CSAdaptive3d.h"
#include "mesher/control/ControlSpaceGrid.h"
#include "mesher/control/PerThreadState.h"
#include "mesher/core/MeshOptions.h"

namespace aniso {

template <int D>
class CSMesh : public std::conditional_t<D == 2, CSAdaptive2d, CSAdaptive3d> {
  using Adaptive = std::conditional_t<D == 2, CSAdaptive2d, CSAdaptive3d>;

 public:
  using Vec = Eigen::Matrix<double, D, 1>;
  using typename Adaptive::VertexModifier;
  using typename Adaptive::VertexVisitor;

  // ControlSpace2d / ControlSpace3d
  Box<D> bounds() const override { return mesh_.bounds(); }
  std::uint64_t revision() const override { return mesh_.revision(); }

  // CSAdaptive2d / CSAdaptive3d
  void insertDiscreteSource(const Vec& x, const Metric<D>& sizing) override { mesh_.insertDiscrete(x, sizing); }
  bool initialized() const override { return mesh_.valued(); }
  std::size_t pendingSourceCount() const override { return mesh_.pendingSources(); }
  int smoothGradation(double gamma) override { return mesh_.smoothGradation(gamma); }
  void forEachControlVertex(const VertexVisitor& visit) const override { mesh_.forEachVertex(visit); }
  void modifyControlVertices(const VertexModifier& modify) override { mesh_.modifyVertices(modify); }
  /// Every vertex of the background mesh, the 4 / 8 box corners included.
  std::size_t controlVertexCount() const override { return mesh_.vertexCount(); }

  // background-mesh specifics
  const BackgroundMesh<D>& structure() const { return mesh_; }
  BackgroundInterpolation interpolation() const { return mesh_.options().interpolation; }
  void setInterpolation(BackgroundInterpolation method) { mesh_.setInterpolation(method); }
  /// Elements and per-vertex tensors for visualisation (cellSize 3, VTK_TRIANGLE / cellSize
  /// 4, dim 3, VTK_TETRA).
  ControlSpaceGrid grid() const { return mesh_.grid(); }
  /// Throws MeshingError naming the first broken invariant (BackgroundMesh::validate).
  void validate() const { mesh_.validate(); }

 protected:
  /// Throws InputError for an empty box or bad parameters / options.
  CSMesh(const Box<D>& bounds, const SizingParameters& params, const BackgroundMeshOptions& options)
      : mesh_(bounds, params, options), hints_([] { return std::make_unique<MeshLocateHint<D>>(); }) {}
  void initializeVertexMetrics() override { mesh_.initializeVertices(); }

  BackgroundMesh<D> mesh_;
  PerThreadState<MeshLocateHint<D>> hints_;
};

}  // namespace aniso
