#include "mesher/adapt/LpMetric.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include <Eigen/Geometry>

#include "mesher/core/Error.h"
#include "mesher/metric/SymmetricEigen.h"

namespace aniso {
namespace {

/// Bisection steps on log D: the bracket spans at most ~60 decades, 200 halvings reach 1e-12.
constexpr int kMaxBisection = 200;
constexpr double kBisectionTolerance = 1e-9;

/// A node's |H| in its basis (d eigenvalues, eigenvectors in space).
struct NodeHessian {
  Vec3 mu = Vec3::Zero();       ///< |eigenvalues| (first d used)
  Mat3 dirs = Mat3::Identity();  ///< columns: eigenvectors in space (dim 2: the third is the normal)
  double base[3] = {0, 0, 0};    ///< det|H|^(−1/(2p+d)) μ_k
  double weight = 0;
};

std::vector<NodeHessian> decompose(const std::vector<Mat3>& hs, const std::vector<double>& w,
                                   const std::vector<Vec3>& normals, const LpMetricParameters& p) {
  const int d = p.dim;
  std::vector<NodeHessian> out(hs.size());
  double muMax = 0;
  for (std::size_t i = 0; i < hs.size(); ++i) {
    NodeHessian& n = out[i];
    n.weight = w[i];
    if (d == 3) {
      const SymmetricEigen<3> e = symmetricEigen(Mat3(0.5 * (hs[i] + hs[i].transpose())));
      n.mu = e.values.cwiseAbs();
      n.dirs = e.vectors;
    } else {
      const Vec3 nn = normals[i];
      if (nn.squaredNorm() == 0) {
        n.weight = 0;
        continue;
      }
      Vec3 t1, t2;
      tangentFrame(nn, t1, t2);
      Eigen::Matrix<double, 3, 2> t;
      t.col(0) = t1;
      t.col(1) = t2;
      const Mat2 h2 = t.transpose() * hs[i] * t;
      const SymmetricEigen<2> e = symmetricEigen(Mat2(0.5 * (h2 + h2.transpose())));
      n.mu.head<2>() = e.values.cwiseAbs();
      n.dirs.col(0) = t * e.vectors.col(0);
      n.dirs.col(1) = t * e.vectors.col(1);
      n.dirs.col(2) = nn;
    }
    for (int k = 0; k < d; ++k) muMax = std::max(muMax, n.mu[k]);
  }
  if (!(muMax > 0) || !std::isfinite(muMax))
    throw MeshingError("the field's Hessian is zero everywhere (a linear field): nothing to adapt to");
  const double floor = kHessianFloor * muMax;
  for (NodeHessian& n : out) {
    double det = 1;
    for (int k = 0; k < d; ++k) {
      n.mu[k] = std::max(n.mu[k], floor);
      det *= n.mu[k];
    }
    const double f = std::pow(det, -1.0 / (2 * p.norm + d));
    for (int k = 0; k < d; ++k) n.base[k] = f * n.mu[k];
  }
  return out;
}

/// The clamped eigenvalues of D · base.
void eigenvalues(const NodeHessian& n, double D, const LpMetricParameters& p, double lambda[3]) {
  const double lo = 1 / (p.hmax * p.hmax), hi = 1 / (p.hmin * p.hmin);
  double top = 0;
  for (int k = 0; k < p.dim; ++k) {
    lambda[k] = std::clamp(D * n.base[k], lo, hi);
    top = std::max(top, lambda[k]);
  }
  const double floorA = top / (p.anisotropy * p.anisotropy);
  for (int k = 0; k < p.dim; ++k) lambda[k] = std::max(lambda[k], floorA);
}

/// √det of the node's metric restricted to a facet: dim 3, the plane normal to `dir`
/// (det M · dirᵀ M⁻¹ dir); dim 2, the line along `dir` (dirᵀ M dir).
double restrictedRoot(const NodeHessian& n, const double* l, const Vec3& dir, int dim) {
  double s = 0;
  for (int k = 0; k < dim; ++k) {
    const double c = n.dirs.col(k).dot(dir);
    s += dim == 3 ? c * c / l[k] : c * c * l[k];
  }
  return std::sqrt(dim == 3 ? s * l[0] * l[1] * l[2] : s);
}

double nodesFor(const std::vector<NodeHessian>& ns, const std::vector<BoundaryFacet>& boundary, double D,
                const LpMetricParameters& p) {
  double c = 0, cb = 0;
  for (const NodeHessian& n : ns) {
    double l[3], det = 1;
    eigenvalues(n, D, p, l);
    for (int k = 0; k < p.dim; ++k) det *= l[k];
    c += n.weight * std::sqrt(det);
  }
  if (kBoundaryNodesPerComplexity[p.dim] > 0)
    for (const BoundaryFacet& f : boundary) {
      double sum = 0;
      int count = 0;
      for (int v : f.nodes) {
        if (v < 0) continue;
        double l[3];
        eigenvalues(ns[v], D, p, l);
        sum += restrictedRoot(ns[v], l, f.direction, p.dim);
        ++count;
      }
      cb += f.measure * sum / count;
    }
  return kInteriorNodesPerComplexity[p.dim] * c + kBoundaryNodesPerComplexity[p.dim] * cb;
}

double errorFor(const std::vector<NodeHessian>& ns, double D, const LpMetricParameters& p) {
  const double cd = p.dim == 2 ? 1.0 / 8 : 1.0 / 10;
  double s = 0;
  for (const NodeHessian& n : ns) {
    double l[3], e = 0;
    eigenvalues(n, D, p, l);
    for (int k = 0; k < p.dim; ++k) e += n.mu[k] / l[k];
    s += n.weight * std::pow(cd * e, p.norm);
  }
  return std::pow(s, 1 / p.norm);
}

/// log-bisection of an increasing g(D) = goal between lo and hi.
double solve(const std::function<double(double)>& g, double goal, double lo, double hi, bool& limited) {
  if (g(lo) >= goal) return limited = true, lo;
  if (g(hi) <= goal) return limited = true, hi;
  for (int it = 0; it < kMaxBisection && hi / lo > 1 + kBisectionTolerance; ++it) {
    const double mid = std::sqrt(lo * hi);
    (g(mid) < goal ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

}  // namespace

LpMetric lpMetric(const std::vector<Mat3>& hessians, const std::vector<double>& measures,
                  const std::vector<Vec3>& normals, const std::vector<BoundaryFacet>& boundary,
                  const LpMetricParameters& p) {
  if (p.dim != 2 && p.dim != 3) throw MeshingError("lpMetric: dim must be 2 or 3");
  if (!(p.norm >= 1)) throw MeshingError("lpMetric: the norm p must be at least 1");
  if (!(p.hmin > 0) || !(p.hmax >= p.hmin)) throw MeshingError("lpMetric: need 0 < hmin <= hmax");
  if (!(p.anisotropy >= 1)) throw MeshingError("lpMetric: the anisotropy limit must be at least 1");
  if ((p.targetNodes > 0) == (p.error > 0)) throw MeshingError("lpMetric: give a target node count or an error");
  if (measures.size() != hessians.size() || (p.dim == 2 && normals.size() != hessians.size()))
    throw MeshingError("lpMetric: one Hessian, measure (and normal in 2D) per node");
  const std::vector<NodeHessian> ns = decompose(hessians, measures, normals, p);
  double bmin = HUGE_VAL, bmax = 0;
  for (const NodeHessian& n : ns)
    for (int k = 0; k < p.dim; ++k) bmin = std::min(bmin, n.base[k]), bmax = std::max(bmax, n.base[k]);
  // every eigenvalue at 1/hmax² below lo, at 1/hmin² above hi
  const double lo = 1 / (p.hmax * p.hmax) / bmax, hi = 1 / (p.hmin * p.hmin) / bmin;
  LpMetric out;
  double D;
  if (p.targetNodes > 0) {
    D = solve([&](double x) { return nodesFor(ns, boundary, x, p); }, p.targetNodes, lo, hi, out.limited);
  } else {  // the error decreases with D
    D = solve([&](double x) { return -errorFor(ns, x, p); }, -p.error, lo, hi, out.limited);
  }
  out.predictedNodes = nodesFor(ns, boundary, D, p);
  out.predictedError = errorFor(ns, D, p);
  out.metrics.reserve(ns.size());
  for (const NodeHessian& n : ns) {
    double l[3] = {0, 0, 1 / (p.hmax * p.hmax)};
    eigenvalues(n, D, p, l);
    Mat3 t = Mat3::Zero();
    for (int k = 0; k < 3; ++k) t += l[k] * n.dirs.col(k) * n.dirs.col(k).transpose();
    out.metrics.push_back(Metric3d::fromTensor(0.5 * (t + t.transpose())));
  }
  return out;
}

}  // namespace aniso
