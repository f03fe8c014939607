#include "mesher/metric/CurvatureSizing.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesher/core/Error.h"

namespace aniso {

CurvatureSizing CurvatureSizing::from(const SizingParameters& p, double modelDiagonal) {
  CurvatureSizing s;
  s.curvatureRatio = p.curvatureRatio;
  s.hMin = p.hminFor(modelDiagonal);
  s.hMax = p.hmaxFor(modelDiagonal);
  s.anisotropy = p.anisotropy;
  s.contourAnisotropy = p.contourAnisotropyEff();
  s.chordDeviation = p.chordDeviationRel * modelDiagonal;
  s.check();
  return s;
}

void CurvatureSizing::check() const {
  auto bad = [](const char* name, double v, const char* rule) {
    throw MeshingError(std::string("curvature sizing: ") + name + " = " + std::to_string(v) + " " + rule);
  };
  if (!(std::isfinite(curvatureRatio) && curvatureRatio > 0)) bad("gamma_c", curvatureRatio, "must be > 0");
  if (!(std::isfinite(hMin) && hMin > 0)) bad("h_min", hMin, "must be > 0");
  if (!(std::isfinite(hMax) && hMax >= hMin)) bad("h_max", hMax, "must be >= h_min");
  if (!(std::isfinite(anisotropy) && anisotropy >= 1)) bad("gamma_a", anisotropy, "must be >= 1");
  if (!(std::isfinite(contourAnisotropy) && contourAnisotropy >= 1 && contourAnisotropy <= anisotropy))
    bad("gamma_ac", contourAnisotropy, "must be in [1, gamma_a]");
  if (!(std::isfinite(chordDeviation) && chordDeviation >= 0)) bad("chord deviation", chordDeviation, "must be >= 0");
}

double CurvatureSizing::length(double curvature) const {
  if (!std::isfinite(curvature)) throw MeshingError("curvature sizing: curvature is not finite");
  const double k = std::abs(curvature);
  double h = k * hMax <= curvatureRatio ? hMax : curvatureRatio / k;  // eq. 2.41 (k = 0: no division)
  if (chordDeviation > 0 && 8 * chordDeviation < k * h * h) h = std::sqrt(8 * chordDeviation / k);
  return std::max(h, hMin);
}

}  // namespace aniso
