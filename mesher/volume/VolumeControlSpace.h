#pragma once
// buildVolumeControlSpace — the initial adaptive control space of one solid (thesis
// sec. 3.5.2, alg. 3.4; eq. 3.3):
//   1 bounding box of the solid's boundary nodes (enlarged by kVolumeBoxMargin of its
//     diagonal);
//   2 a new ACS (CSOctree3d);
//   3 the user's 3D sizing: the global metric and every source whose box meets the solid's
//     (CSAdaptive3d::insertExtendedSource: ball, capsule, box);
//   4 the metric of the surface patches: for every boundary node of the solid, the blend
//     (eq. 2.18) of the metrics of its incident boundary triangles; a triangle's metric is
//     its simplex metric (eq. 2.33) in its plane, eigen-form (e1, e2, h1, h2), extended
//     to 3D with e3 = the triangle normal and h3 = min(h1, h2), bounded by eq. 3.3
//     (λ3 ≤ γ_a min(λ1, λ2) with λ = 1/h, i.e. h3 ≥ max(h1, h2) / γ_a). The thesis leaves
//     the exact λ3 open ("calculated as" an upper bound); min(h1, h2) keeps an isotropic
//     surface isotropic in the volume and gives the anisotropic cylinder its short
//     circumferential size in the radial direction. Inserted as point sources, then
//     intersected with h_max (SizingParameters::hmaxFor of the model diagonal) everywhere;
//   5 anisotropy limited to γ_a; smoothed to γ_M (alg. 3.4 step 6, sec. 3.3.4).
// Only the triangles of faces of the solid's shells (outer and voids) are used.
// Throws MeshingError when the solid has no boundary triangle.
//
// The sizing convention of the volume (README, "Options"): a size h (--size, --hmax, the
// surface's curvature and the user's sources alike) asks for surface triangles of edge
// length h, as in 2D, and for tetrahedra of edge length f·h, f = kVolumeLengthFactor —
// the meaning Gmsh gives its sizes in 3D (its HXT and Delaunay meshes have interior edges
// of about 1.45 h). buildVolumeControlSpace returns the user's metric M (the one the
// surface was meshed in); the tetrahedra are made, improved and measured in
// M_v = M / f (VolumeMetricSpace: transformation tensor M / f, metric tensor 𝓜 / f²):
// η_M, μ_M, q(K) of eq. 5.2, the l_M > 1.5 edge check and the eq. 6.1/6.2 predictions.
// The boundary triangles are then 1/f long in M_v; the refinement grades from them to
// unit tets in the interior within a layer or two (q(K) ≥ q_t keeps the short tets at the
// boundary, CCS points grow away from it).
#include <memory>

#include "mesher/control/ControlSpace3d.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/model/Model.h"
#include "mesher/sizing/UserSizing.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

/// f of the sizing convention above: the tetrahedra's edge length over the surface's.
/// Measured on the unit cube at size 0.02 (tets; interior edges over h; referee mean ratio):
/// f = 1: 1.32 M, 1.00, 0.873; 1.3: 619 k; 1.35: 558 k; 1.4: 504 k, 1.39, 0.868 (tets
/// touching the boundary 0.844) — Gmsh HXT: 491 k, 1.45, 0.815. 1.4 lands at 1.03 x HXT's count.
inline constexpr double kVolumeLengthFactor = 1.4;

/// M_v of the convention above: the metric of `user` with every requested length times
/// `factor` (M / factor). Thread safety and revision as `user`'s.
class VolumeMetricSpace final : public ControlSpace3d {
 public:
  explicit VolumeMetricSpace(std::shared_ptr<const ControlSpace3d> user, double factor = kVolumeLengthFactor);
  Metric3d getMetric(const Vec3& x) const override { return user_->getMetric(x).scaled(inverse_); }
  Box3 bounds() const override { return user_->bounds(); }
  std::uint64_t revision() const override { return user_->revision(); }
  /// f: lengths measured in M_v times f are lengths in the user's metric.
  double factor() const { return factor_; }
  const ControlSpace3d& user() const { return *user_; }

 private:
  std::shared_ptr<const ControlSpace3d> user_;
  double factor_, inverse_;
};

/// Relative enlargement of the control space's box around the solid's boundary nodes.
inline constexpr double kVolumeBoxMargin = 0.01;

std::shared_ptr<ControlSpace3d> buildVolumeControlSpace(const Model& model, const SurfaceMesh& surface, int solid,
                                                        const SizingParameters& sizing, const UserSizing* user);

}  // namespace aniso
