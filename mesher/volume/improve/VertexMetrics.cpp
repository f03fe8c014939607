#include "mesher/volume/improve/VertexMetrics.h"

#include "mesher/metric/MeanRatio.h"
#include "mesher/volume/TetQuality.h"

namespace aniso::improve3d {

void VertexMetrics::sync() {
  const std::size_t old = m_.size();
  m_.resize(mesh_.numVertices(), Mat3::Identity());
  for (std::size_t v = old; v < m_.size(); ++v)
    if (mesh_.vertexTet(del3d::VertexId(static_cast<std::uint32_t>(v))).valid())
      m_[v] = cs_.getMetric(mesh_.point(del3d::VertexId(static_cast<std::uint32_t>(v)))).matrix();
}

void VertexMetrics::refresh(del3d::VertexId v) { m_[v.index] = cs_.getMetric(mesh_.point(v)).matrix(); }

double VertexMetrics::eta(const std::uint32_t* v) const {
  const Mat3 m = tetMetric(v);
  return meanRatio(Vec3(m * mesh_.point(del3d::VertexId(v[0]))), Vec3(m * mesh_.point(del3d::VertexId(v[1]))),
                   Vec3(m * mesh_.point(del3d::VertexId(v[2]))), Vec3(m * mesh_.point(del3d::VertexId(v[3]))));
}

double VertexMetrics::etaWith(const std::uint32_t* v, std::uint32_t moved, const Vec3& p) const {
  const Mat3 m = tetMetric(v);
  Vec3 q[4];
  for (int i = 0; i < 4; ++i) q[i] = m * (v[i] == moved ? p : mesh_.point(del3d::VertexId(v[i])));
  return meanRatio(q[0], q[1], q[2], q[3]);
}

double VertexMetrics::metricMinDihedral(del3d::TetId t) const {
  const std::uint32_t* v = mesh_.tetVertices(t);
  const Mat3 m = tetMetric(v);
  return tetMinDihedral(m * mesh_.point(del3d::VertexId(v[0])), m * mesh_.point(del3d::VertexId(v[1])),
                        m * mesh_.point(del3d::VertexId(v[2])), m * mesh_.point(del3d::VertexId(v[3])));
}

}  // namespace aniso::improve3d
