#include "mesher/volume/improve/VertexMetrics.h"

#include <Eigen/Geometry>
#include <algorithm>

#include "mesher/metric/MeanRatio.h"
#include "mesher/volume/TetQuality.h"

namespace aniso::improve3d {

namespace {

/// Signed η³ = 12³ · 9 V² / (Σ l²)³ · sign(V) of MeanRatio.h without the cube root.
double meanRatioCubed(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4) {
  const Vec3 a = p2 - p1, b = p3 - p1, c = p4 - p1;
  const double sum = a.squaredNorm() + b.squaredNorm() + c.squaredNorm() + (p3 - p2).squaredNorm() +
                     (p4 - p2).squaredNorm() + (p4 - p3).squaredNorm();
  const double volume = a.dot(b.cross(c)) / 6;
  if (!(sum > 0)) return 0.0;
  return std::copysign(1728.0 * 9 * volume * volume / (sum * sum * sum), volume);
}

}  // namespace

void VertexMetrics::setMetric(std::size_t v, const Mat3& m) {
  m_[v] = m;
  iso_[v] = isotropicScale(m) > 0;
}

void VertexMetrics::sync() {
  const std::size_t old = m_.size();
  m_.resize(mesh_.numVertices(), Mat3::Identity());
  iso_.resize(mesh_.numVertices(), 1);
  for (std::size_t v = old; v < m_.size(); ++v) {
    const del3d::VertexId id(static_cast<std::uint32_t>(v));
    if (mesh_.vertexTet(id).valid()) setMetric(v, cs_.getMetric(mesh_.point(id)).matrix());
  }
}

void VertexMetrics::refresh(del3d::VertexId v) { setMetric(v.index, cs_.getMetric(mesh_.point(v)).matrix()); }

double VertexMetrics::score(const std::uint32_t* v) const {
  const Vec3 p[4] = {mesh_.point(del3d::VertexId(v[0])), mesh_.point(del3d::VertexId(v[1])),
                     mesh_.point(del3d::VertexId(v[2])), mesh_.point(del3d::VertexId(v[3]))};
  const double e = meanRatioCubed(p[0], p[1], p[2], p[3]);
  if (isotropic(v)) return e;
  const Mat3 m = tetMetric(v);
  const double metric = meanRatioCubed(m * p[0], m * p[1], m * p[2], m * p[3]);
  return guardEuclidean_ ? std::min(metric, e) : metric;
}

double VertexMetrics::scorePoints(const Vec3* p, const Mat3& m, bool isotropicTensor) const {
  const double e = meanRatioCubed(p[0], p[1], p[2], p[3]);
  if (isotropicTensor) return e;
  const double metric = meanRatioCubed(m * p[0], m * p[1], m * p[2], m * p[3]);
  return guardEuclidean_ ? std::min(metric, e) : metric;
}

double VertexMetrics::scoreWith(const std::uint32_t* v, std::uint32_t moved, const Vec3& p) const {
  Vec3 q[4];
  for (int i = 0; i < 4; ++i) q[i] = v[i] == moved ? p : mesh_.point(del3d::VertexId(v[i]));
  const double e = meanRatioCubed(q[0], q[1], q[2], q[3]);
  if (isotropic(v)) return e;
  const Mat3 m = tetMetric(v);
  const double metric = meanRatioCubed(m * q[0], m * q[1], m * q[2], m * q[3]);
  return guardEuclidean_ ? std::min(metric, e) : metric;
}

bool VertexMetrics::isSliver(del3d::TetId t, double metricAngle, double euclideanAngle) const {
  const std::uint32_t* v = mesh_.tetVertices(t);
  const Vec3 p[4] = {mesh_.point(del3d::VertexId(v[0])), mesh_.point(del3d::VertexId(v[1])),
                     mesh_.point(del3d::VertexId(v[2])), mesh_.point(del3d::VertexId(v[3]))};
  const DihedralRange r = tetDihedralRange(p[0], p[1], p[2], p[3]);
  if (r.minDeg < euclideanAngle || r.maxDeg > 180 - euclideanAngle) return true;
  if (isotropic(v)) return r.minDeg < metricAngle;
  return metricMinDihedral(t) < metricAngle;
}

double VertexMetrics::metricMinDihedral(del3d::TetId t) const {
  const std::uint32_t* v = mesh_.tetVertices(t);
  const Mat3 m = isotropic(v) ? Mat3::Identity() : tetMetric(v);
  return tetMinDihedral(m * mesh_.point(del3d::VertexId(v[0])), m * mesh_.point(del3d::VertexId(v[1])),
                        m * mesh_.point(del3d::VertexId(v[2])), m * mesh_.point(del3d::VertexId(v[3])));
}

}  // namespace aniso::improve3d
