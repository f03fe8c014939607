#pragma once
// CSMesh2d — the background-mesh adaptive control space for surface meshing (thesis
// sec. 3.4, fig. 3.6, 6.3.1) over a rectangle of the parametric plane: control vertices
// with metrics in the nodes of a Delaunay triangulation (identity metric) of the control
// vertices. The sibling of CSQuadtree2d: same SizingParameters (ε_M, ε_δ, l_Mmax), same
// CSAdaptive2d operations, same grid() export (VTK_TRIANGLE cells).
//
// Structure and field: BackgroundMesh2d (see BackgroundMesh.h for the interpolation
// sets A_s / A_t / A_o of sec. 3.4.5 with the inverse squared-distance weights of eq. 3.2
// in S^R and the ε_M shortcut, the kernel's enclosing box whose 4 corners are control
// vertices too, and the thread-safety design). The interpolation set and the check
// points of the continuous adaptation are chosen in BackgroundMeshOptions (defaults A_t
// and the thesis' centroid; measurements there).
//
// Procedures:
//   insertDiscreteSource  fresh (sec. 3.4.1 "setting initial control space"): the point
//                         becomes a control vertex carrying its metric, inserted with local
//                         retriangulation (Bowyer–Watson of the kernel) — unless a vertex
//                         carrying a metric is closer than ε_M in M_sQ M_p (among the
//                         vertices of the containing triangle and of its edge neighbours),
//                         which is then intersected with M_sQ instead.
//                         initializeControlVertices gives the box corners (and any vertex
//                         without a metric) metrics by extrapolation along the mesh edges.
//                         valued ("updating", as 3.3.1): nothing when δ_M(M_sQ, field) or
//                         δ_M(min_M(M_sQ, field), field) < ε_δ; proximity as above; when
//                         the containing triangle has an edge longer than l_Mmax in M_sQ
//                         M_p, Q is inserted with min_M(M_sQ, field) (the mesh form of the
//                         "split") and every edge from Q still longer than l_Mmax gets a
//                         ring vertex at metric distance l_Mmax carrying the previous
//                         field, for at most maxRingRounds rounds — so the source acts
//                         within about l_Mmax element lengths, as the quadtree's leaves
//                         of that size do; otherwise the vertices of the containing
//                         triangle are intersected with M_sQ (as the leaf corners).
//   setContinuousSource   sec. 3.4.2, see BackgroundMesh::setContinuous; then folds in
//                         point / extended sources collected while fresh.
//   adaptToParameterization  sec. 3.4.3 (as 3.3.3): M_p cached at the vertices, triangles
//                         refined where M_p varies by more than ε_δ.
//   smoothGradation       sec. 3.4.4, edge marking until no change.
// For repeated queries at nearby points wrap calls in a MetricQueryCache2d (sec. 3.2.4
// item 3).
// The operations shared with CSMesh3d are in CSMesh<D> (CSMesh.h).
// Thread safety: getMetric(), parameterizationAt() and the other const methods may run
// concurrently on a control space that is not being modified. getMetric(uv) keeps the
// last located triangle per thread (PerThreadState); getMetric(uv, hint) takes it from
// the caller.
#include <memory>

#include "mesher/control/CSMesh.h"

namespace aniso {

class CSMesh2d final : public CSMesh<2> {
 public:
  /// Throws InputError for an empty box or bad parameters / options.
  CSMesh2d(const Box2& bounds, const SizingParameters& params, const BackgroundMeshOptions& options = {})
      : CSMesh<2>(bounds, params, options) {}

  // ControlSpace2d
  SurfaceMetricAt getMetric(const Vec2& uv) const override;

  // CSAdaptive2d
  void setContinuousSource(const ControlSpace2d& source) override;
  void adaptToParameterization(const ParametricSurface& surface, double gMin) override;
  Mat2 parameterizationAt(const Vec2& uv) const override { return mesh_.auxAt(uv, hints_.local()); }

  // background-mesh specifics
  /// getMetric with a caller-owned location hint (one per thread).
  SurfaceMetricAt getMetric(const Vec2& uv, MeshLocateHint2d& hint) const;
  std::size_t triangleCount() const { return mesh_.triangulation().numTriangles(); }

 private:
  std::unique_ptr<ParametricSurface> surface_;  ///< clone for M_p at new vertices
};

}  // namespace aniso
