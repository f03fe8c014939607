#pragma once
// buildVolumeControlSpace — the initial adaptive control space of one solid (thesis
// sec. 3.5.2, alg. 3.4; eq. 3.3):
//   1 bounding box of the solid's boundary nodes (enlarged by kVolumeBoxMargin of its
//     diagonal);
//   2 a new ACS (CSOctree3d);
//   3 the user's 3D sizing: the global metric and every source whose box meets the solid's
//     (CSAdaptive3d::insertExtendedSource: ball, capsule, box), and the point sources in
//     the box (mesher/sizing/PointSizing.h);
//   4 the metric of the surface patches: for every boundary node of the solid, the blend
//     (eq. 2.18) of the metrics of its incident boundary triangles; a triangle's metric is
//     its simplex metric (eq. 2.33) in its plane, eigen-form (e1, e2, h1, h2), extended
//     to 3D with e3 = the triangle normal and h3 = min(h1, h2), bounded by eq. 3.3
//     (λ3 ≤ γ_a min(λ1, λ2) with λ = 1/h, i.e. h3 ≥ max(h1, h2) / γ_a). The thesis leaves
//     the exact λ3 open ("calculated as" an upper bound); min(h1, h2) keeps an isotropic
//     surface isotropic in the volume and gives the anisotropic cylinder its short
//     circumferential size in the radial direction. Inserted as point sources, then
//     intersected with h_max (SizingParameters::hmaxFor of the model diagonal) everywhere;
//   5 anisotropy limited to γ_a; smoothed (alg. 3.4 step 6, sec. 3.3.4) so that γ_M holds
//     in M_v (volumeGradation): the tets are f times longer than M's unit, so M's size may
//     grow only 1/f as fast per length (eq. 2.27's slope a_max / f).
// Only the triangles of faces of the solid's shells (outer and voids) are used.
// Throws MeshingError when the solid has no boundary triangle.
//
// The sizing convention of the volume (docs/sizing.md, "Sizes in 3D"): a size h (--size, --hmax, the
// surface's curvature and the user's sources alike) asks for surface triangles of edge
// length h, as in 2D, and for tetrahedra of edge length f·h inside the solid, f =
// kVolumeLengthFactor — the meaning Gmsh gives its sizes in 3D (its HXT and Delaunay meshes
// have interior edges of about 1.45 h). buildVolumeControlSpace returns the user's metric M
// (the one the surface was meshed in); the tetrahedra are made, improved and measured in
// M_v (VolumeMetricSpace): M on the solid's surface, M / f from one unit length of M
// (kVolumeTransitionLayers) inside on, the length factor linear in the metric distance to
// the closest surface point in between (BoundaryDistance.h; transformation tensor; metric
// tensor 𝓜 / f² away from the surface). Every consumer measures a tet from its vertices'
// tensors (η_M, μ_M, the eq. 6.1/6.2 predictions and the improvement in their mean; the
// refinement's q(K) of eq. 5.2 and l_M > 1.5 edge check by eq. 2.18, the mean of their
// length tensors, VolumeRefinement.h), so the size grades from h at the boundary to f·h
// about one layer of tets inside: the tets on a boundary triangle are shaped for it, not
// for a surface 1/f too fine (with M / f up to the boundary, the tets at the boundary were
// poorer than those inside: docs/measurements.md). What kept μ_M below 1 on graded meshes
// was not mainly the step from M at the surface nodes to M / f, but the refinement
// measuring tets in the mean of the vertices' tensors (VolumeRefinement.h); the grading
// then adds a little (see kVolumeTransitionLayers; docs/measurements.md).
#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "mesher/control/ControlSpace3d.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/model/Model.h"
#include "mesher/sizing/UserSizing.h"
#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/BoundaryDistance.h"

namespace aniso {

/// f of the sizing convention above: the tetrahedra's edge length over the surface's.
/// Larger f makes fewer tets but costs quality where the mesh is graded (fewer layers
/// between fine and coarse); 1.4 keeps graded parts at the 0.80 bar and makes about Gmsh
/// HXT's count on a uniform cube (docs/measurements.md).
inline constexpr double kVolumeLengthFactor = 1.4;

/// The depth, in unit lengths of M, over which M_v grades from M at the surface to M / f
/// (VolumeMetricSpace with a surface): about one layer of tets, a size slope of (f − 1) /
/// kVolumeTransitionLayers = 0.4, below γ_M's (eq. 2.27: 1.2 at γ_M 4). Grading over one
/// unit raises μ_M against a step at the surface nodes for about the same tets; over two
/// the count grows to the limit of what is asked (docs/measurements.md).
inline constexpr double kVolumeTransitionLayers = 1.0;

/// M_v of the convention above: the metric of `user` with every requested length times
/// `factor` (M / factor), except at the points of `boundary` (exact coordinates: the solid's
/// surface nodes), where it is M. With `surface` (the solid's boundary triangles), M_v grades
/// from M on the surface to M / factor at the metric distance kVolumeTransitionLayers (the
/// length in M(x) of the vector from x to its closest surface point): the length factor is
/// 1 + (factor − 1) min(1, l / kVolumeTransitionLayers). Thread safety and revision as
/// `user`'s.
class VolumeMetricSpace final : public ControlSpace3d {
 public:
  VolumeMetricSpace(std::shared_ptr<const ControlSpace3d> user, std::span<const Vec3> boundary = {},
                    double factor = kVolumeLengthFactor, std::shared_ptr<const TriangleTree> surface = nullptr);
  Metric3d getMetric(const Vec3& x) const override {
    const Metric3d m = user_->getMetric(x);
    return m.scaled(1.0 / lengthFactor(x, m));
  }
  Box3 bounds() const override { return user_->bounds(); }
  std::uint64_t revision() const override { return user_->revision(); }
  /// f.
  double factor() const { return factor_; }
  /// Lengths in M_v at x times this are lengths in M: 1 at a boundary node, f away from
  /// the surface (graded in between with a surface).
  double lengthFactorAt(const Vec3& x) const { return lengthFactor(x, user_->getMetric(x)); }
  /// lengthFactorAt(x) to rounding, from mv = M_v(x) (the matrix getMetric(x) returned, held
  /// by the caller) instead of a query of M: M = f·mv, so the factor solves f = 1 + (f_max −
  /// 1) min(1, f·|mv (x − c)| / L) (c the closest surface point, L kVolumeTransitionLayers),
  /// whose one solution is f_max when f_max·|mv (x − c)| ≥ L, else 1 / (1 − (f_max − 1)
  /// |mv (x − c)| / L); with h_v ≥ mv's largest size, a point farther than L h_v / f_max
  /// from the surface has f_max (|mv (x − c)| ≥ |x − c| / h_v; to 1e-9 relative where the
  /// distance and L h_v / f_max are equal up to rounding), a surface node 1. No query of M;
  /// a distance search (within L h_v / f_max) only near the surface. For the quality
  /// report's μ_M in M (TetQuality.h). factor < 1: lengthFactorAt.
  double lengthFactorFrom(const Vec3& x, const Mat3& mv) const;
  bool onBoundary(const Vec3& x) const;
  const ControlSpace3d& user() const { return *user_; }

 private:
  using Key = std::array<std::uint64_t, 3>;
  static Key key(const Vec3& x);
  static std::size_t hash(const Key& k);
  /// The length factor at x, m = M(x).
  double lengthFactor(const Vec3& x, const Metric3d& m) const;

  std::shared_ptr<const ControlSpace3d> user_;
  double factor_;
  /// The boundary points' keys, open addressing with linear probing (one or two cache
  /// lines per lookup); empty slots hold kEmpty (a NaN's bits: never a point's key).
  std::vector<Key> boundary_;
  std::size_t mask_ = 0;
  std::shared_ptr<const TriangleTree> surface_;
};

/// The gradation ratio for M whose size slope (eq. 2.27: a_max = 2 (γ − 1) / (γ + 1)) is
/// 1/factor of gamma's: γ_M = gamma measured in M_v = M / factor. gamma ≤ 1: unchanged.
/// γ_M 4 and f 1.4 give 2.5.
double volumeGradation(double gamma, double factor);

/// Relative enlargement of the control space's box around the solid's boundary nodes.
inline constexpr double kVolumeBoxMargin = 0.01;

/// faceTriangles (optional): the surface's triangle indices per model face
/// (trianglesByFace), built here when not given; a caller meshing many solids passes the one
/// it built. The result does not depend on it.
std::shared_ptr<ControlSpace3d> buildVolumeControlSpace(const Model& model, const SurfaceMesh& surface, int solid,
                                                        const SizingParameters& sizing, const UserSizing* user,
                                                        const std::vector<std::vector<int>>* faceTriangles = nullptr);

}  // namespace aniso
