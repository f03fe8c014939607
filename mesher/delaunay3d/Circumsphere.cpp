#include "mesher/delaunay3d/Circumsphere.h"

#include <algorithm>
#include <limits>

#include "mesher/predicates/Predicates.h"

namespace aniso::del3d {
namespace {

constexpr double kU = 0x1p-53;
constexpr double kSqrt3 = 1.7320508075688774;  // rounded up
/// η of the certificate (Circumsphere.h).
constexpr double kEta = 0x1p-30;
/// Magnitudes for which the first-order bounds hold and the squared certificate below stays
/// finite (no underflow or overflow on the way; an underflow of its right side only refuses).
constexpr double kMinL = 0x1p-200, kMaxL = 0x1p200;
constexpr double kMinR2 = 0x1p-400, kMaxR2 = 0x1p400;

/// circumcentreOffset, also returning det and L (the largest squared edge length at a).
bool offset(const double* a, const double* b, const double* c, const double* d, double centre[3], double& det,
            double& l) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double vwx = vy * wz - vz * wy, vwy = vz * wx - vx * wz, vwz = vx * wy - vy * wx;
  const double wux = wy * uz - wz * uy, wuy = wz * ux - wx * uz, wuz = wx * uy - wy * ux;
  const double uvx = uy * vz - uz * vy, uvy = uz * vx - ux * vz, uvz = ux * vy - uy * vx;
  det = (ux * vwx + uy * vwy) + uz * vwz;
  const double uu = (ux * ux + uy * uy) + uz * uz, vv = (vx * vx + vy * vy) + vz * vz;
  const double ww = (wx * wx + wy * wy) + wz * wz;
  l = std::max({uu, vv, ww});
  if (!(std::fabs(det) > kFlatCircumsphere * l * std::sqrt(l))) return false;
  const double twoDet = 2 * det;
  centre[0] = ((uu * vwx + vv * wux) + ww * uvx) / twoDet;
  centre[1] = ((uu * vwy + vv * wuy) + ww * uvy) / twoDet;
  centre[2] = ((uu * vwz + vv * wuz) + ww * uvz) / twoDet;
  return std::isfinite(centre[0]) && std::isfinite(centre[1]) && std::isfinite(centre[2]);
}

}  // namespace

bool circumcentreOffset(const double* a, const double* b, const double* c, const double* d, double centre[3]) {
  double det, l;
  return offset(a, b, c, d, centre, det, l);
}

void cachedSphere(const double* a, const double* b, const double* c, const double* d, CachedSphere& s) {
  double o[3], det, l;
  if (!offset(a, b, c, d, o, det, l)) {
    s.centre[0] = a[0], s.centre[1] = a[1], s.centre[2] = a[2];
    s.radius2 = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  for (int k = 0; k < 3; ++k) s.centre[k] = a[k] + o[k];
  const double r2 = (o[0] * o[0] + o[1] * o[1]) + o[2] * o[2];
  // The certificate of Circumsphere.h.
  const double absDet = std::fabs(det), l32 = l * std::sqrt(l);
  const double m = std::max({std::fabs(o[0]), std::fabs(o[1]), std::fabs(o[2])});
  const double cmax = std::max({std::fabs(s.centre[0]), std::fabs(s.centre[1]), std::fabs(s.centre[2])});
  const double detError = 12 * kU * kSqrt3 * l32;
  // E_c ≤ η r̃ multiplied by |d̂et| and squared (no division, no root; the few roundings of
  // this comparison are far inside the factor 2.6 between τ and the bound).
  const double ecDet = kSqrt3 * ((42 * kU * l * l + 42 * kU * m * l32) + kU * (m + cmax) * absDet);
  const double etaDet = kEta * absDet, lhs = ecDet * ecDet;
  const bool certified = l >= kMinL && l <= kMaxL && r2 >= kMinR2 && r2 <= kMaxR2 && detError <= 0.5 * absDet &&
                         std::isfinite(lhs) && lhs <= etaDet * etaDet * r2;
  s.radius2 = certified ? r2 : -r2;
}

bool sphereFilterAgrees(const double* a, const double* b, const double* c, const double* d, const double* p) {
  const int side = sphereSide(cachedSphere(a, b, c, d), p);
  if (side == 0) return true;
  const double orient = predicates::orient3d(a, b, c, d);
  if (orient == 0) return false;  // a flat tet is never certified
  const double in = predicates::insphere(a, b, c, d, p);
  const int exact = in == 0 ? 0 : ((in > 0) == (orient > 0) ? 1 : -1);
  return side == exact;
}

}  // namespace aniso::del3d
