#include "mesher/volume/improve/VertexMetrics.h"

#include <Eigen/Geometry>
#include <algorithm>

#include "mesher/metric/MeanRatio.h"
#include "mesher/volume/TetQuality.h"

namespace aniso::improve3d {

namespace {

constexpr double kDegToRad = 0.017453292519943295;

/// Signed η³ = 12³ · 9 V² / (Σ l²)³ · sign(V) of MeanRatio.h without the cube root (the
/// hot function of the improvement: inlined into its callers).
[[gnu::always_inline]] inline double meanRatioCubed(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const Vec3 a = p2 - p1, b = p3 - p1, c = p4 - p1;
  const double sum = a.squaredNorm() + b.squaredNorm() + c.squaredNorm() + (p3 - p2).squaredNorm() +
                     (p4 - p2).squaredNorm() + (p4 - p3).squaredNorm();
  const double volume = a.dot(b.cross(c)) / 6;
  if (!(sum > 0)) return 0.0;
  return std::copysign(1728.0 * 9 * volume * volume / (sum * sum * sum), volume);
}

/// Signed (min_e sin θ_e / sin θ_regular)³ over the six dihedral angles θ_e (sin θ_e =
/// 3 V |e| / (2 A_1 A_2), A_1, A_2 the areas of the two faces at e): small for a sliver,
/// a cap or a wedge (an angle near 0° or 180°), not for a spire (three vertices close
/// together: a low mean ratio, every dihedral angle large).
double dihedralSineCubed(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const Vec3 p[4] = {p1, p2, p3, p4};
  double area2[4];  // squared twice the area of the face opposite vertex k
  for (int k = 0; k < 4; ++k) {
    const Vec3& a = p[(k + 1) % 4];
    area2[k] = (p[(k + 2) % 4] - a).cross(p[(k + 3) % 4] - a).squaredNorm();
  }
  const double volume6 = (p2 - p1).dot((p3 - p1).cross(p4 - p1));
  // the edge (i, j) lies on the faces opposite the two other vertices (k, l)
  static constexpr int kEdgeFaces[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                           {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  double smallest = 1e300;  // min |e|² / (area_k area_l)²
  for (const auto& e : kEdgeFaces) {
    const double denominator = area2[e[2]] * area2[e[3]];
    if (!(denominator > 0)) return 0.0;
    smallest = std::min(smallest, (p[e[1]] - p[e[0]]).squaredNorm() / denominator);
  }
  // sin θ_e = 3 V |e| / (2 A_k A_l) = (V6 / 2) |e| / (area_k area_l / 2) = V6 |e| / (area_k area_l)
  const double sine = std::min(1.0, std::abs(volume6) * std::sqrt(smallest) / kRegularDihedralSine);
  return std::copysign(sine * sine * sine, volume6);
}

}  // namespace

double VertexMetrics::guarded(double metric, const Vec3* p, bool euclidean) const {
  if (!guardEuclidean_) return metric;
  const double e = euclidean ? metric : meanRatioCubed(p[0], p[1], p[2], p[3]);
  return std::min({metric, e, dihedralSineCubed(p[0], p[1], p[2], p[3])});
}

void VertexMetrics::setMetric(std::size_t v, const Mat3& m) {
  m_[v] = m;
  iso_[v] = isotropicScale(m) > 0;
}

void VertexMetrics::sync(const refine3d::VertexTensorTable* seed) {
  const std::size_t old = m_.size();
  m_.resize(mesh_.numVertices(), Mat3::Identity());
  iso_.resize(mesh_.numVertices(), 1);
  for (std::size_t v = old; v < m_.size(); ++v) {
    const del3d::VertexId id(static_cast<std::uint32_t>(v));
    if (!mesh_.vertexTet(id).valid()) continue;
    setMetric(v, seed && v < seed->size() ? seed->at(v) : cs_.getMetric(mesh_.point(id)).matrix());
  }
}

void VertexMetrics::refresh(del3d::VertexId v) { setMetric(v.index, cs_.getMetric(mesh_.point(v)).matrix()); }

double VertexMetrics::score(const std::uint32_t* v) const {
  const Vec3 p[4] = {mesh_.point(del3d::VertexId(v[0])), mesh_.point(del3d::VertexId(v[1])),
                     mesh_.point(del3d::VertexId(v[2])), mesh_.point(del3d::VertexId(v[3]))};
  if (isotropic(v)) {
    const double e = meanRatioCubed(p[0], p[1], p[2], p[3]);
    return guardEuclidean_ ? guarded(e, p, true) : e;
  }
  const Mat3 m = tetMetric(v);
  const double e = meanRatioCubed(m * p[0], m * p[1], m * p[2], m * p[3]);
  return guardEuclidean_ ? guarded(e, p, false) : e;
}

double VertexMetrics::scorePoints(const Vec3* p, const Mat3& m, bool isotropicTensor) const {
  if (isotropicTensor) return guarded(meanRatioCubed(p[0], p[1], p[2], p[3]), p, true);
  return guarded(meanRatioCubed(m * p[0], m * p[1], m * p[2], m * p[3]), p, false);
}

double VertexMetrics::scoreWith(const std::uint32_t* v, std::uint32_t moved, const Vec3& p) const {
  Vec3 q[4];
  for (int i = 0; i < 4; ++i) q[i] = v[i] == moved ? p : mesh_.point(del3d::VertexId(v[i]));
  if (isotropic(v)) {
    const double e = meanRatioCubed(q[0], q[1], q[2], q[3]);
    return guardEuclidean_ ? guarded(e, q, true) : e;
  }
  const Mat3 m = tetMetric(v);
  const double e = meanRatioCubed(m * q[0], m * q[1], m * q[2], m * q[3]);
  return guardEuclidean_ ? guarded(e, q, false) : e;
}

double VertexMetrics::etaGradient(const std::uint32_t* v, std::uint32_t moved, Vec3& gradient) const {
  gradient = Vec3::Zero();
  int k = 0;
  while (k < 4 && v[k] != moved) ++k;
  if (k == 4) return 0;
  Vec3 q[4];
  for (int i = 0; i < 4; ++i) q[i] = mesh_.point(del3d::VertexId(v[i]));
  const double D = (q[1] - q[0]).dot((q[2] - q[0]).cross(q[3] - q[0]));
  if (!(D > 0)) return 0;
  // ∂D/∂q_k: the normal of the opposite face, scaled so that its dot with q_k − q_a is D
  const int a = (k + 1) % 4, b = (k + 2) % 4, c = (k + 3) % 4;
  const Vec3 n = (q[b] - q[a]).cross(q[c] - q[a]);
  const double h = n.dot(q[k] - q[a]);
  if (h == 0) return 0;
  const Vec3 dD = n * (D / h);
  const bool iso = isotropic(v);
  const Mat3 t = iso ? Mat3::Identity() : tetMetric(v);
  const Mat3 tt = t.transpose() * t;
  double sigma = 0;
  Vec3 dSigma = Vec3::Zero();
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Vec3 e = q[i] - q[j];
      sigma += e.dot(tt * e);
    }
  for (int j = 0; j < 4; ++j)
    if (j != k) dSigma += 2 * (tt * (q[k] - q[j]));
  if (!(sigma > 0)) return 0;
  const double scaledD = iso ? D : D * t.determinant();
  if (!(scaledD > 0)) return 0;
  const double eta = std::cbrt(432.0 * scaledD * scaledD) / sigma;
  gradient = eta * ((2.0 / 3.0) * dD / D - dSigma / sigma);
  return eta;
}

namespace {
/// The η³ above which no dihedral angle is within `angle` (degrees) of 0° or 180°: 2 sin²,
/// raised by a relative margin for the rounding of both sides.
double excludingScore(double angle) {
  constexpr double kMargin = 1e-9;
  const double s = std::sin(std::min(angle, 90.0) * kDegToRad);
  return 2 * s * s * (1 + kMargin);
}
}  // namespace

VertexMetrics::SliverAngles::SliverAngles(double metricAngle, double euclideanAngle)
    : cosMetric(std::cos(metricAngle * kDegToRad)),
      cosEuclidean(std::cos(euclideanAngle * kDegToRad)),
      cosIsotropic(std::cos(std::max(metricAngle, euclideanAngle) * kDegToRad)),
      etaMetric(excludingScore(metricAngle)),
      etaEuclidean(excludingScore(euclideanAngle)),
      etaIsotropic(excludingScore(std::max(metricAngle, euclideanAngle))) {}

bool VertexMetrics::isSliver(del3d::TetId t, const SliverAngles& a) const {
  const std::uint32_t* v = mesh_.tetVertices(t);
  const Vec3 p[4] = {mesh_.point(del3d::VertexId(v[0])), mesh_.point(del3d::VertexId(v[1])),
                     mesh_.point(del3d::VertexId(v[2])), mesh_.point(del3d::VertexId(v[3]))};
  // Euclidean: an angle below θ_E or above 180° − θ_E; isotropic: also below θ_M. A mean
  // ratio above the bound of the angle answers first.
  const double eta = meanRatioCubed(p[0], p[1], p[2], p[3]);
  if (isotropic(v))
    return !(eta > a.etaIsotropic) && dihedralCosineOutside(p[0], p[1], p[2], p[3], a.cosIsotropic, -a.cosEuclidean);
  if (!(eta > a.etaEuclidean) && dihedralCosineOutside(p[0], p[1], p[2], p[3], a.cosEuclidean, -a.cosEuclidean))
    return true;
  const Mat3 m = tetMetric(v);
  const Vec3 q[4] = {m * p[0], m * p[1], m * p[2], m * p[3]};
  return !(meanRatioCubed(q[0], q[1], q[2], q[3]) > a.etaMetric) &&
         dihedralCosineOutside(q[0], q[1], q[2], q[3], a.cosMetric, -2.0);
}

}  // namespace aniso::improve3d
