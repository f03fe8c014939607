#include "mesher/metric/MetricIntersection.h"

#include <Eigen/Cholesky>

#include "mesher/core/Error.h"
#include "mesher/metric/SymmetricEigen.h"

namespace aniso {

namespace {

/// Which input the intersection equals (within the tolerance), or neither.
enum class Outcome { First, Second, Mixed };

template <int D>
struct Reduced {
  Eigen::Matrix<double, D, D> tensor;
  Outcome outcome;
};

template <int D>
Reduced<D> reduce(const Eigen::Matrix<double, D, D>& t1, const Eigen::Matrix<double, D, D>& t2,
                  double tol) {
  using Mat = Eigen::Matrix<double, D, D>;
  using Vec = Eigen::Matrix<double, D, 1>;
  const Eigen::LLT<Mat> llt(t1);
  if (llt.info() != Eigen::Success || !t2.allFinite())
    throw MeshingError("metric intersection: input metric tensor is not positive definite");
  // C = L⁻¹ 𝓜2 L⁻ᵀ. The fixed-size inverse is a closed form; Eigen's triangular solve
  // with a matrix right-hand side goes through its generic blocked kernel, which costs
  // several times more for 2×2 and 3×3.
  const Mat l = llt.matrixL();
  const Mat linv = l.inverse();
  const Mat c = symmetrize<D>(linv * t2 * linv.transpose());
  const SymmetricEigen<D> e = symmetricEigen(c);
  if (!e.values.allFinite())
    throw MeshingError("metric intersection: simultaneous reduction failed (non-finite eigenvalues)");
  if (e.values.maxCoeff() <= 1 + tol) return {t1, Outcome::First};
  if (e.values.minCoeff() >= 1 - tol) return {t2, Outcome::Second};
  const Vec lambda = e.values.cwiseMax(1.0);
  const Mat lq = l * e.vectors;
  return {symmetrize<D>(lq * lambda.asDiagonal() * lq.transpose()), Outcome::Mixed};
}

}  // namespace

template <int D>
Eigen::Matrix<double, D, D> intersectTensors(const Eigen::Matrix<double, D, D>& t1,
                                             const Eigen::Matrix<double, D, D>& t2,
                                             bool* firstChanged, double tol) {
  const Reduced<D> r = reduce<D>(t1, t2, tol);
  if (firstChanged) *firstChanged = r.outcome != Outcome::First;
  return r.tensor;
}

template <int D>
Metric<D> intersect(const Metric<D>& a, const Metric<D>& b) {
  const Reduced<D> r = reduce<D>(a.tensor(), b.tensor(), kIntersectionTolerance);
  if (r.outcome == Outcome::First) return a;
  if (r.outcome == Outcome::Second) return b;
  return Metric<D>::fromTensor(r.tensor);
}

template <int D>
bool intersectInto(Metric<D>& a, const Metric<D>& b, double tol) {
  const Reduced<D> r = reduce<D>(a.tensor(), b.tensor(), tol);
  if (r.outcome == Outcome::First) return false;
  a = r.outcome == Outcome::Second ? b : Metric<D>::fromTensor(r.tensor);
  return true;
}

template <int D>
Metric<D> intersect(std::span<const Metric<D>> metrics) {
  if (metrics.empty()) throw MeshingError("metric intersection: no metric given");
  if (metrics.size() == 1) return metrics[0];
  // Tensor form throughout; remember when the running result is exactly one input.
  auto t = metrics[0].tensor();
  std::size_t same = 0;  // index of the input equal to t, or metrics.size() if mixed
  for (std::size_t i = 1; i < metrics.size(); ++i) {
    const Reduced<D> r = reduce<D>(t, metrics[i].tensor(), kIntersectionTolerance);
    t = r.tensor;
    if (r.outcome == Outcome::Second) same = i;
    else if (r.outcome == Outcome::Mixed) same = metrics.size();
  }
  return same < metrics.size() ? metrics[same] : Metric<D>::fromTensor(t);
}

template Eigen::Matrix<double, 2, 2> intersectTensors<2>(const Eigen::Matrix<double, 2, 2>&,
                                                         const Eigen::Matrix<double, 2, 2>&, bool*, double);
template Eigen::Matrix<double, 3, 3> intersectTensors<3>(const Eigen::Matrix<double, 3, 3>&,
                                                         const Eigen::Matrix<double, 3, 3>&, bool*, double);
template Metric<2> intersect(const Metric<2>&, const Metric<2>&);
template Metric<3> intersect(const Metric<3>&, const Metric<3>&);
template bool intersectInto(Metric<2>&, const Metric<2>&, double);
template bool intersectInto(Metric<3>&, const Metric<3>&, double);
template Metric<2> intersect(std::span<const Metric<2>>);
template Metric<3> intersect(std::span<const Metric<3>>);

}  // namespace aniso
