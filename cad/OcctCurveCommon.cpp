#include "cad/detail/OcctCurveCommon.h"

#include <Precision.hxx>

#include <algorithm>
#include <sstream>

namespace aniso::cad::detail {

void OcctCurveRange::cover(double natFirst, double natLast) {
  const double lo = std::min(first, last), hi = std::max(first, last);
  tMin = Precision::IsInfinite(natFirst) ? lo : std::min(natFirst, lo);
  tMax = Precision::IsInfinite(natLast) ? hi : std::max(natLast, hi);
}

void failOcctCurve(const std::string& name, const char* kind, const char* what, double t, const std::string& message) {
  std::ostringstream s;
  s.precision(17);
  s << name << ": OCCT failed to evaluate the " << kind << "'s " << what << " at t = " << t << ": " << message;
  throw MeshingError(s.str());
}

}  // namespace aniso::cad::detail
