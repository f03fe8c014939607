#pragma once
// Parameters and the length law of the curvature metric sources (sec. 2.4.2–2.4.3).
//
//   h(χ) = max(min(γ_c / |χ|, sqrt(8 δ / |χ|), h_max), h_min)   (eq. 2.41 and the h_1 of eq. 2.46)
//
// γ_c is the ratio of edge length to curvature radius; χ = 0 (flat) gives h_max. The sign
// of a curvature (which side the surface bends to) does not matter for sizing. δ > 0, the
// chord deviation, bounds the distance of a chord of length h from the curve (h²κ/8): on
// large radii, where γ_c alone leaves long chords (not in the thesis; 0 turns it off).
#include "mesher/core/MeshOptions.h"

namespace aniso {

struct CurvatureSizing {
  double curvatureRatio = 0.15;   ///< γ_c > 0
  double hMin = 1e-4;             ///< h_min > 0
  double hMax = 0.5;              ///< h_max ≥ h_min
  double anisotropy = 5.0;        ///< γ_a ≥ 1 (eq. 2.42)
  double contourAnisotropy = 2.0; ///< γ_ac, 1 ≤ γ_ac ≤ γ_a (eq. 2.46)
  double chordDeviation = 0;      ///< δ ≥ 0, absolute; 0: no chord bound

  /// From the user's options for a model of the given diagonal (h_min, h_max absolute or
  /// relative, γ_ac capped at γ_a). Throws MeshingError when the result fails check().
  static CurvatureSizing from(const SizingParameters& p, double modelDiagonal);
  /// Throws MeshingError naming the first invalid parameter.
  void check() const;
  /// Eq. 2.41 for one curvature value.
  double length(double curvature) const;
};

}  // namespace aniso
