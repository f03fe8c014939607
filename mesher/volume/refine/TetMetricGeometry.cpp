#include "mesher/volume/refine/TetMetricGeometry.h"

#include <Eigen/LU>
#include <cmath>

#include "mesher/delaunay3d/Circumsphere.h"

namespace aniso::refine3d {

// The arithmetic of the Inserter's sphere cache (del3d::circumcentreOffset, at a = 0: the
// differences u − 0 are exact), so that q(K) is the same from either.
bool circumcentreOffset(const Vec3& u, const Vec3& v, const Vec3& w, Vec3& centre) {
  constexpr double kOrigin[3] = {0, 0, 0};
  double c[3];
  if (!del3d::circumcentreOffset(kOrigin, u.data(), v.data(), w.data(), c)) return false;
  centre = Vec3(c[0], c[1], c[2]);
  return true;
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
