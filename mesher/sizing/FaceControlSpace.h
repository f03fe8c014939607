#pragma once
// The initial adaptive control space of one face (thesis alg. 3.2, sec. 3.5.1):
//   1 bounding rectangle of the face in (u, v)
//   2 a new ACS (CSQuadtree2d)
//   3 initialized with the surface curvature (eq. 2.35–2.42), or with h_max everywhere
//     when the curvature is off (--no-curvature)
//   4 intersected with the user's control spaces: an analytic 2D sizing (analytic models)
//     and the user's 3D sources, bounded to [h_min, h_max], restricted to the surface
//   6 updated with the contour curvature of every edge of the face (eq. 2.45–2.46),
//     probed along the pcurves and inserted as point sources (with the curvature on)
//   7 adapted to the parameterization (3.3.3)
//   8 smoothed to the gradation ratio γ_M (3.3.4)
// The later updates of alg. 3.1 (boundary segment lengths, proximity) belong to the
// surface mesher.
#include <memory>

#include "mesher/control/CSQuadtree2d.h"
#include "mesher/control/ControlSpace2d.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/model/Model.h"
#include "mesher/sizing/UserSizing.h"

namespace aniso {

struct FaceSizingInput {
  const Model* model = nullptr;
  int face = -1;                               ///< 0-based index into model->faces
  SizingParameters params;
  const ControlSpace2d* analytic = nullptr;    ///< user's 2D sizing in this face's (u, v), optional
  const UserSizing* user = nullptr;            ///< user's 3D sources, optional
  /// The chord deviation (absolute, VolumeChordBound.h); negative: the model-wide one of
  /// `params`.
  double chordDeviation = -1;
};

/// The g_min guard of M_p (sec. 2.2.1) for a model: one parametric unit maps to at least
/// h_min in space, so M_p stays regular at poles without affecting regular regions.
double parameterizationGuard(const SizingParameters& params, double modelDiagonal);

/// Builds the initial control space of the face. Throws MeshingError naming the face when
/// it has no usable surface, its parametric bounds are empty or its geometry cannot be
/// evaluated.
std::unique_ptr<CSQuadtree2d> buildFaceControlSpace(const FaceSizingInput& in);

}  // namespace aniso
