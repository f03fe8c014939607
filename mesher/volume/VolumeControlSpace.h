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
#include <memory>

#include "mesher/control/ControlSpace3d.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/model/Model.h"
#include "mesher/sizing/UserSizing.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

/// Relative enlargement of the control space's box around the solid's boundary nodes.
inline constexpr double kVolumeBoxMargin = 0.01;

std::shared_ptr<ControlSpace3d> buildVolumeControlSpace(const Model& model, const SurfaceMesh& surface, int solid,
                                                        const SizingParameters& sizing, const UserSizing* user);

}  // namespace aniso
