#include "mesher/metric/SimplexMetric.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "mesher/core/Error.h"
#include "mesher/metric/SymmetricEigen.h"

namespace aniso {
namespace {

/// J⁻ᵀ G_ref J⁻¹ for the edge matrix J (columns P_i − P_1); `name` for the message.
template <int D>
Eigen::Matrix<double, D, D> unitEdgeTensor(const Eigen::Matrix<double, D, D>& j, double longest,
                                           const char* name) {
  using Mat = Eigen::Matrix<double, D, D>;
  const double det = j.determinant();
  if (!j.allFinite() || !std::isfinite(longest))
    throw MeshingError(std::string("simplex metric: ") + name + " has non-finite coordinates");
  if (!(std::abs(det) > kDegenerateSimplex * std::pow(longest, D)))
    throw MeshingError(std::string("simplex metric: degenerate ") + name + " (zero " +
                       (D == 2 ? "area" : "volume") + ")");
  Mat gref = Mat::Constant(0.5);
  gref.diagonal().setOnes();
  const Mat jinv = j.inverse();
  return symmetrize<D>(jinv.transpose() * gref * jinv);
}

}  // namespace

Mat2 simplexMetricTensor(const Vec2& p1, const Vec2& p2, const Vec2& p3) {
  Mat2 j;
  j << p2 - p1, p3 - p1;
  const double longest = std::max({(p2 - p1).norm(), (p3 - p1).norm(), (p3 - p2).norm()});
  return unitEdgeTensor<2>(j, longest, "triangle");
}

Mat3 simplexMetricTensor(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  Mat3 j;
  j << p2 - p1, p3 - p1, p4 - p1;
  const double longest = std::max({(p2 - p1).norm(), (p3 - p1).norm(), (p4 - p1).norm(),
                                   (p3 - p2).norm(), (p4 - p2).norm(), (p4 - p3).norm()});
  return unitEdgeTensor<3>(j, longest, "tetrahedron");
}

Metric2d simplexMetric(const Vec2& p1, const Vec2& p2, const Vec2& p3) {
  return Metric2d::fromTensor(simplexMetricTensor(p1, p2, p3));
}

Metric3d simplexMetric(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  return Metric3d::fromTensor(simplexMetricTensor(p1, p2, p3, p4));
}

}  // namespace aniso
