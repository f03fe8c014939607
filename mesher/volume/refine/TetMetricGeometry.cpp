#include "mesher/volume/refine/TetMetricGeometry.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

namespace aniso::refine3d {
namespace {
/// |det| of the edge vectors relative to the cube of their longest length below which the
/// circumsphere is not computed (the tet is flat to rounding).
constexpr double kFlatTet = 1e-14;
}  // namespace

bool circumcentreOffset(const Vec3& u, const Vec3& v, const Vec3& w, Vec3& centre) {
  const Vec3 vw = v.cross(w), wu = w.cross(u), uv = u.cross(v);
  const double det = u.dot(vw);
  const double l = std::max({u.squaredNorm(), v.squaredNorm(), w.squaredNorm()});
  if (!(std::abs(det) > kFlatTet * l * std::sqrt(l))) return false;
  centre = (u.squaredNorm() * vw + v.squaredNorm() * wu + w.squaredNorm() * uv) / (2 * det);
  return std::isfinite(centre.x()) && std::isfinite(centre.y()) && std::isfinite(centre.z());
}

double metricSphereQuality(const Mat3& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  Vec3 centre;
  if (!circumcentreOffset(m * (b - a), m * (c - a), m * (d - a), centre)) return 0.0;
  const double r = kIdealCircumradius / centre.norm();
  return r * r * r;
}

bool metricCircumcentre(const Mat3& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, Vec3& out) {
  Vec3 centre;
  if (!circumcentreOffset(m * (b - a), m * (c - a), m * (d - a), centre)) return false;
  out = a + m.inverse() * centre;
  return true;
}

}  // namespace aniso::refine3d
