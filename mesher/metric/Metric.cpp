#include "mesher/metric/Metric.h"

#include <cmath>
#include <sstream>

#include "mesher/core/Error.h"
#include "mesher/metric/SymmetricEigen.h"

namespace aniso {
namespace {

/// Tolerance on |e_i·e_j| and |‖e_i‖ − 1| for "orthonormal" directions.
constexpr double kOrthonormalTol = 1e-6;
/// Largest accepted relative asymmetry |A − Aᵀ|max / |A|max of a given matrix.
constexpr double kSymmetryTol = 1e-9;

template <int D>
std::string describe(const Eigen::Matrix<double, D, D>& m) {
  std::ostringstream s;
  s.precision(17);
  s << "[";
  for (int i = 0; i < D; ++i) {
    for (int j = 0; j < D; ++j) s << (j ? " " : "") << m(i, j);
    s << (i + 1 < D ? "; " : "");
  }
  s << "]";
  return s.str();
}

[[noreturn]] void fail(int dim, const std::string& what) {
  throw MeshingError("Metric" + std::to_string(dim) + "d: " + what);
}

void checkLength(int dim, double h, const char* name) {
  if (!(std::isfinite(h) && h > 0)) {
    std::ostringstream s;
    s << "requested length " << name << " = " << h << " is not finite and positive";
    fail(dim, s.str());
  }
}

/// Symmetric, finite, SPD after symmetrisation; `what` names the kind of matrix.
template <int D>
Eigen::Matrix<double, D, D> checkedSpd(const Eigen::Matrix<double, D, D>& m, const char* what) {
  if (!m.allFinite()) fail(D, std::string(what) + " is not finite: " + describe<D>(m));
  const double scale = m.cwiseAbs().maxCoeff();
  if ((m - m.transpose()).cwiseAbs().maxCoeff() > kSymmetryTol * scale)
    fail(D, std::string(what) + " is not symmetric: " + describe<D>(m));
  const Eigen::Matrix<double, D, D> s = symmetrize<D>(m);
  if (!isSymmetricPositiveDefinite(s))
    fail(D, std::string(what) + " is not positive definite: " + describe<D>(m));
  return s;
}

template <int D>
void checkOrthonormal(const Eigen::Matrix<double, D, D>& e) {
  const Eigen::Matrix<double, D, D> gram = e.transpose() * e;
  if (!gram.allFinite() ||
      (gram - Eigen::Matrix<double, D, D>::Identity()).cwiseAbs().maxCoeff() > kOrthonormalTol)
    fail(D, "main directions are not orthonormal: " + describe<D>(e));
}

}  // namespace

template <int D>
Metric<D> Metric<D>::isotropic(double h) {
  checkLength(D, h, "h");
  return Metric(Mat::Identity() / h);
}

template <int D>
Metric<D> Metric<D>::fromAngle(double alpha, double h1, double h2)
  requires(D == 2)
{
  if (!std::isfinite(alpha)) fail(2, "angle is not finite");
  checkLength(2, h1, "h1");
  checkLength(2, h2, "h2");
  const double c = std::cos(alpha), s = std::sin(alpha);
  const double i1 = 1 / h1, i2 = 1 / h2;
  Mat m;
  m(0, 0) = i1 * c * c + i2 * s * s;  // eq. 2.4
  m(0, 1) = m(1, 0) = (i1 - i2) * s * c;
  m(1, 1) = i1 * s * s + i2 * c * c;
  return Metric(m);
}

template <int D>
Metric<D> Metric<D>::fromDirections(const Vec3& e1, const Vec3& e2, const Vec3& e3, double h1,
                                    double h2, double h3)
  requires(D == 3)
{
  Mat e;
  const Vec3* dirs[3] = {&e1, &e2, &e3};
  for (int i = 0; i < 3; ++i) {
    const double n = dirs[i]->norm();
    if (!(std::isfinite(n) && n > 0)) fail(3, "main direction e" + std::to_string(i + 1) + " is zero or not finite");
    e.col(i) = *dirs[i] / n;
  }
  return fromAxes(e, Vec(h1, h2, h3));
}

template <int D>
Metric<D> Metric<D>::fromAxes(const Mat& directions, const Vec& lengths) {
  checkOrthonormal<D>(directions);
  Vec inv;
  for (int i = 0; i < D; ++i) {
    checkLength(D, lengths(i), ("h" + std::to_string(i + 1)).c_str());
    inv(i) = 1 / lengths(i);
  }
  return Metric(symmetrize<D>(directions * inv.asDiagonal() * directions.transpose()));
}

template <int D>
Metric<D> Metric<D>::fromTransformation(const Mat& m) {
  return Metric(checkedSpd<D>(m, "transformation tensor"));
}

template <int D>
Metric<D> Metric<D>::fromTensor(const Mat& tensor) {
  const Mat t = checkedSpd<D>(tensor, "metric tensor");
  const SymmetricEigen<D> e = symmetricEigen(t);
  if (!(e.values.minCoeff() > 0))
    fail(D, "metric tensor has a non-positive eigenvalue: " + describe<D>(tensor));
  const Vec root = e.values.cwiseSqrt();
  const Mat m = symmetrize<D>(e.vectors * root.asDiagonal() * e.vectors.transpose());
  if (!isSymmetricPositiveDefinite(m))
    fail(D, "square root of the metric tensor is not positive definite: " + describe<D>(tensor));
  return Metric(m);
}

template <int D>
typename Metric<D>::Mat Metric<D>::inverseMatrix() const {
  return symmetrize<D>(m_.inverse());
}

template <int D>
MetricAxes<D> Metric<D>::axes() const {
  const SymmetricEigen<D> e = symmetricEigen(m_);
  // Eigenvalues of M are 1/h_i: ascending eigenvalues give descending lengths.
  MetricAxes<D> a;
  for (int i = 0; i < D; ++i) {
    a.directions.col(i) = e.vectors.col(D - 1 - i);
    a.lengths(i) = 1 / e.values(D - 1 - i);
  }
  if constexpr (D == 3) {
    if (a.directions.determinant() < 0) a.directions.col(2) = -a.directions.col(2);
  }
  return a;
}

template <int D>
MetricAngle2d Metric<D>::angleLengths() const
  requires(D == 2)
{
  const SymmetricEigen<2> e = symmetricEigen(m_);
  MetricAngle2d r;
  r.h1 = 1 / e.values(1);
  r.h2 = 1 / e.values(0);
  r.alpha = std::atan2(e.vectors(1, 1), e.vectors(0, 1));
  // Canonical half-open range (−π/2, π/2]: a direction and its opposite are the same axis.
  if (r.alpha <= -M_PI / 2) r.alpha += M_PI;
  if (r.alpha > M_PI / 2) r.alpha -= M_PI;
  return r;
}

template <int D>
Metric<D> Metric<D>::scaled(double s) const {
  if (!(std::isfinite(s) && s > 0)) fail(D, "scale factor " + std::to_string(s) + " is not finite and positive");
  return Metric(m_ * s);
}

template class Metric<2>;
template class Metric<3>;

}  // namespace aniso
