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
}

double CurvatureSizing::length(double curvature) const {
  if (!std::isfinite(curvature)) throw MeshingError("curvature sizing: curvature is not finite");
  const double k = std::abs(curvature);
  if (k * hMax <= curvatureRatio) return hMax;  // also k = 0: no division
  return std::max(curvatureRatio / k, hMin);    // eq. 2.41
}

}  // namespace aniso
