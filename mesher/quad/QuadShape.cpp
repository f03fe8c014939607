#include "mesher/quad/QuadShape.h"

#include <cmath>

#include "mesher/predicates/Predicates.h"
#include "mesher/quad/QuadQuality.h"
#include "mesher/surface/improve/VertexMetricCache.h"

namespace aniso::quad {

VertexMetrics::VertexMetrics(const QuadMesh2d& mesh, const ControlSpace2d& cs, const ParametricSurface* surface,
                             std::span<const Vec3> nodes)
    : mesh_(mesh), cs_(cs), surface_(surface), nodes_(nodes) {
  const int n = mesh.numVertices();
  s_.assign(n, Mat2::Identity());
  xyz_.assign(n, Vec3::Zero());
  if (surface_)
    for (int v = 0; v < n; ++v) xyz_[v] = pointOf(v);
  known_.assign(n, 0);
  // The fallback for unusable metrics: identity scaled to the mean √det S of the usable
  // vertices (evaluated here for all vertices, in index order, so it is deterministic).
  double sum = 0;
  int count = 0;
  for (int v = 0; v < n; ++v) {
    Mat2 s;
    if (improve::symmetricTransform(cs.getMetric(mesh.uv[v]).transformation(), s)) {
      s_[v] = s;
      known_[v] = 1;
      sum += std::sqrt(s.determinant());
      ++count;
    } else {
      known_[v] = 2;
    }
  }
  if (count > 0) fallback_ = Mat2::Identity() * (sum / count);
  for (int v = 0; v < n; ++v)
    if (known_[v] == 2) s_[v] = fallback_;
}

void VertexMetrics::evaluate(int v) {
  if (static_cast<int>(s_.size()) <= v) {
    s_.resize(v + 1, fallback_);
    xyz_.resize(v + 1, Vec3::Zero());
    known_.resize(v + 1, 0);
  }
  if (surface_) xyz_[v] = pointOf(v);
  Mat2 s;
  s_[v] = improve::symmetricTransform(cs_.getMetric(mesh_.uv[v]).transformation(), s) ? s : fallback_;
  known_[v] = 1;
}

const Mat2& VertexMetrics::at(int v) {
  if (v >= static_cast<int>(known_.size()) || !known_[v]) evaluate(v);
  return s_[v];
}

Vec3 VertexMetrics::pointOf(int v) const {
  const int g = mesh_.node[v];
  if (g >= 0 && g < static_cast<int>(nodes_.size())) return nodes_[g];
  return surface_->point(mesh_.uv[v]);
}

const Vec3* VertexMetrics::point(int v) {
  if (!surface_) return nullptr;
  at(v);
  return &xyz_[v];
}

Mat2 VertexMetrics::element(const Corners& c) {
  const int n = c[3] == kNone ? 3 : 4;
  Mat2 sum = Mat2::Zero();
  for (int k = 0; k < n; ++k) sum += at(c[k]);
  return sum / n;
}

double VertexMetrics::length(int a, int b) {
  const Vec2 e = mesh_.uv[b] - mesh_.uv[a];
  return (0.5 * (at(a) + at(b)) * e).norm();
}

double VertexMetrics::gradation(int a, int b) {
  const Vec2 e = mesh_.uv[b] - mesh_.uv[a];
  const double la = (at(a) * e).norm(), lb = (at(b) * e).norm();
  if (!(la > 0) || !(lb > 0)) return 1.0;
  return la > lb ? la / lb : lb / la;
}

double scaledJacobian(const Mat2& s, const std::array<Vec2, 4>& p) {
  double worst = 1.0;
  for (int k = 0; k < 4; ++k) {
    const Vec2 e1 = s * (p[(k + 1) % 4] - p[k]), e2 = s * (p[(k + 3) % 4] - p[k]);
    const double den = e1.norm() * e2.norm();
    const double sj = den > 0 ? (e1.x() * e2.y() - e1.y() * e2.x()) / den : -1.0;
    worst = std::min(worst, std::isfinite(sj) ? sj : -1.0);
  }
  return worst;
}

double triangleShape(const Mat2& s, const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 e1 = s * (b - a), e2 = s * (c - a), e3 = e2 - e1;
  const double twiceArea = e1.x() * e2.y() - e1.y() * e2.x();
  const double sum = e1.squaredNorm() + e2.squaredNorm() + e3.squaredNorm();
  if (!(sum > 0)) return -1.0;
  const double eta = 2.0 * std::sqrt(3.0) * twiceArea / sum;
  return std::isfinite(eta) ? eta : -1.0;
}

bool convexCCW(const QuadMesh2d& mesh, const Corners& c) {
  const int n = c[3] == kNone ? 3 : 4;
  for (int k = 0; k < n; ++k) {
    const Vec2& a = mesh.uv[c[(k + n - 1) % n]];
    const Vec2& b = mesh.uv[c[k]];
    const Vec2& d = mesh.uv[c[(k + 1) % n]];
    if (!(predicates::orient2d(a.data(), b.data(), d.data()) > 0)) return false;
    if (n == 3) break;  // one orientation decides a triangle
  }
  return true;
}

double elementQuality(const QuadMesh2d& mesh, VertexMetrics& metrics, const Corners& c) {
  if (!convexCCW(mesh, c)) return -1.0;
  const Mat2 s = metrics.element(c);
  if (c[3] == kNone) return triangleShape(s, mesh.uv[c[0]], mesh.uv[c[1]], mesh.uv[c[2]]);
  const double metric = scaledJacobian(s, {mesh.uv[c[0]], mesh.uv[c[1]], mesh.uv[c[2]], mesh.uv[c[3]]});
  if (!metrics.point(c[0])) return metric;
  // Pole corners (two corners on one global node) make a triangle in 3D: judged in metric only.
  for (int k = 0; k < 4; ++k)
    if (mesh.node[c[k]] >= 0 && mesh.node[c[k]] == mesh.node[c[(k + 1) % 4]]) return metric;
  // The scaled Jacobian measures angles only, blind to edge length ratios, so the 3D value
  // is the right one for anisotropic quads too; the metric, averaged over the corners,
  // misjudges elements where the parameterization varies fast (fillets, near poles).
  return scaledJacobian3d(*metrics.point(c[0]), *metrics.point(c[1]), *metrics.point(c[2]), *metrics.point(c[3]));
}

std::vector<std::string> validateGeometry(const QuadMesh2d& mesh) {
  std::vector<std::string> bad;
  for (int e = 0; e < mesh.numElements(); ++e)
    if (mesh.alive(e) && !convexCCW(mesh, mesh.corners[e]))
      bad.push_back("element " + std::to_string(e) + " is not strictly convex and counter-clockwise");
  return bad;
}

}  // namespace aniso::quad
