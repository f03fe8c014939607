#include "mesher/adapt/HessianRecovery.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace aniso {
namespace {

/// The next ring: every neighbour of `patch` not in it (patch stays sorted).
void growPatch(std::vector<int>& patch, const std::vector<std::vector<int>>& nb) {
  std::vector<int> grown = patch;
  for (int v : patch) grown.insert(grown.end(), nb[v].begin(), nb[v].end());
  std::sort(grown.begin(), grown.end());
  grown.erase(std::unique(grown.begin(), grown.end()), grown.end());
  patch.swap(grown);
}

/// Least-squares quadratic on `patch` around node i; false when rank-deficient.
bool fitQuadratic(const PatchMesh& m, const std::vector<double>& f, int i, const std::vector<int>& patch,
                  const Vec3& normal, Mat3& h) {
  const int d = m.dim;
  const int unknowns = d == 3 ? 10 : 6;
  if (static_cast<int>(patch.size()) < unknowns) return false;
  Vec3 t1 = Vec3::UnitX(), t2 = Vec3::UnitY();
  if (d == 2) {
    if (normal.squaredNorm() == 0) return false;
    tangentFrame(normal, t1, t2);
  }
  double s = 0;
  for (int v : patch) s = std::max(s, (m.nodes[v] - m.nodes[i]).norm());
  if (!(s > 0)) return false;
  Eigen::MatrixXd a(patch.size(), unknowns);
  Eigen::VectorXd b(patch.size());
  for (std::size_t r = 0; r < patch.size(); ++r) {
    const Vec3 x = (m.nodes[patch[r]] - m.nodes[i]) / s;
    b[r] = f[patch[r]];
    if (d == 3) {
      a.row(r) << 1, x.x(), x.y(), x.z(), x.x() * x.x(), x.y() * x.y(), x.z() * x.z(), x.x() * x.y(), x.y() * x.z(),
          x.z() * x.x();
    } else {
      const double u = x.dot(t1), w = x.dot(t2);
      a.row(r) << 1, u, w, u * u, w * w, u * w;
    }
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a);
  qr.setThreshold(1e-10);
  if (qr.rank() < unknowns) return false;
  const Eigen::VectorXd c = qr.solve(b);
  const double k = 1.0 / (s * s);
  if (d == 3) {
    h << 2 * c[4], c[7], c[9], c[7], 2 * c[5], c[8], c[9], c[8], 2 * c[6];
    h *= k;
  } else {
    Mat2 h2;
    h2 << 2 * c[3], c[5], c[5], 2 * c[4];
    Eigen::Matrix<double, 3, 2> t;
    t.col(0) = t1;
    t.col(1) = t2;
    h = k * t * h2 * t.transpose();
  }
  return true;
}

std::vector<Mat3> leastSquares(const PatchMesh& m, const std::vector<double>& f) {
  const auto nb = nodeNeighbours(m);
  const auto boundary = boundaryNodes(m);
  const auto normals = nodeNormals(m);
  const int unknowns = m.dim == 3 ? 10 : 6;
  std::vector<Mat3> out(m.nodes.size(), Mat3::Zero());
  for (std::size_t i = 0; i < m.nodes.size(); ++i) {
    if (nb[i].empty()) continue;
    std::vector<int> patch = nb[i];
    patch.insert(std::lower_bound(patch.begin(), patch.end(), static_cast<int>(i)), static_cast<int>(i));
    int rings = 1;
    if (boundary[i] || static_cast<int>(patch.size()) < unknowns + kMinPatchExtra) {
      growPatch(patch, nb);
      rings = 2;
    }
    const Vec3 n = normals.empty() ? Vec3::Zero() : normals[i];
    for (;;) {
      if (fitQuadratic(m, f, static_cast<int>(i), patch, n, out[i])) break;
      if (rings++ >= kMaxPatchRings) {
        out[i].setZero();
        break;
      }
      growPatch(patch, nb);
    }
  }
  return out;
}

/// The gradient of the linear interpolant of values g at a cell's corners (in the
/// triangle's plane on a surface); false for a degenerate cell.
bool cellGradient(const PatchMesh& m, std::size_t c, const double* g, Vec3& grad) {
  const int* v = m.conn.data() + m.offsets[c];
  if (m.dim == 3) {
    Mat3 j;
    for (int k = 0; k < 3; ++k) j.col(k) = m.nodes[v[k + 1]] - m.nodes[v[0]];
    const Eigen::FullPivLU<Mat3> lu(j);
    if (!lu.isInvertible()) return false;
    grad = j.transpose().fullPivLu().solve(Vec3(g[1] - g[0], g[2] - g[0], g[3] - g[0]));
    return true;
  }
  Eigen::Matrix<double, 3, 2> j;
  j.col(0) = m.nodes[v[1]] - m.nodes[v[0]];
  j.col(1) = m.nodes[v[2]] - m.nodes[v[0]];
  const Mat2 jtj = j.transpose() * j;
  if (!(std::abs(jtj.determinant()) > 0)) return false;
  grad = j * jtj.inverse() * Vec2(g[1] - g[0], g[2] - g[0]);
  return true;
}

std::vector<Mat3> doubleL2(const PatchMesh& m, const std::vector<double>& f) {
  const std::size_t n = m.nodes.size();
  const int k = m.corners();
  std::vector<double> weight(n, 0.0);
  std::vector<Vec3> grad(n, Vec3::Zero());
  std::vector<char> usable(m.cellCount(), 0);
  for (std::size_t c = 0; c < m.cellCount(); ++c) {
    double g[4];
    for (int i = 0; i < k; ++i) g[i] = f[m.conn[m.offsets[c] + i]];
    Vec3 gc;
    if (!cellGradient(m, c, g, gc)) continue;
    usable[c] = 1;
    const double w = cellMeasure(m, c);
    for (int i = 0; i < k; ++i) {
      const int v = m.conn[m.offsets[c] + i];
      grad[v] += gc * w;
      weight[v] += w;
    }
  }
  for (std::size_t v = 0; v < n; ++v)
    if (weight[v] > 0) grad[v] /= weight[v];
  std::vector<Mat3> out(n, Mat3::Zero());
  std::vector<double> w2(n, 0.0);
  for (std::size_t c = 0; c < m.cellCount(); ++c) {
    if (!usable[c]) continue;
    Mat3 h;
    bool ok = true;
    for (int d = 0; d < 3 && ok; ++d) {
      double g[4];
      for (int i = 0; i < k; ++i) g[i] = grad[m.conn[m.offsets[c] + i]][d];
      Vec3 row;
      ok = cellGradient(m, c, g, row);
      h.row(d) = row.transpose();
    }
    if (!ok) continue;
    const double w = cellMeasure(m, c);
    const Mat3 sym = 0.5 * w * (h + h.transpose());
    for (int a = m.offsets[c]; a < m.offsets[c + 1]; ++a) {
      out[m.conn[a]] += sym;
      w2[m.conn[a]] += w;
    }
  }
  for (std::size_t v = 0; v < n; ++v)
    if (w2[v] > 0) out[v] /= w2[v];
  return out;
}

}  // namespace

std::vector<Mat3> recoverHessian(const PatchMesh& m, const std::vector<double>& f, HessianMethod method) {
  return method == HessianMethod::LeastSquares ? leastSquares(m, f) : doubleL2(m, f);
}

}  // namespace aniso
