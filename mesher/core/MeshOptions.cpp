#include "mesher/core/MeshOptions.h"

#include <cmath>

namespace aniso {
namespace {
bool finitePositive(double x) { return std::isfinite(x) && x > 0; }
}  // namespace

std::string SizingParameters::check() const {
  if (size && !finitePositive(*size)) return "--size must be a positive number";
  if (hmax && !finitePositive(*hmax)) return "--hmax must be a positive number";
  if (hmin && !finitePositive(*hmin)) return "--hmin must be a positive number";
  if (hmax && hmin && *hmin > *hmax) return "--hmin is above --hmax: lower --hmin or raise --hmax";
  if (size && hmin && *hmin > *size) return "--hmin is above --size: lower --hmin or raise --size";
  if (!finitePositive(hmaxRel) || hmaxRel > 10) return "--hmax-rel must be in (0, 10]";
  if (!finitePositive(hminRel) || hminRel > hmaxRel) return "--hmin-rel must be in (0, hmax-rel]";
  if (!finitePositive(curvatureRatio) || curvatureRatio > 10) return "--curvature-ratio must be in (0, 10]";
  if (!std::isfinite(chordDeviationRel) || chordDeviationRel < 0 || chordDeviationRel > 1)
    return "--chord-deviation-rel must be in [0, 1]";
  if (!std::isfinite(gradation) || gradation < 1) return "--gradation must be at least 1";
  if (!std::isfinite(anisotropy) || anisotropy < 1 || anisotropy > 1e6) return "--anisotropy must be in [1, 1e6]";
  if (!std::isfinite(contourAnisotropy) || contourAnisotropy < 1 || contourAnisotropy > 1e6)
    return "--contour-anisotropy must be in [1, 1e6]";
  return {};
}

}  // namespace aniso
