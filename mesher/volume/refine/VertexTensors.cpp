#include "mesher/volume/refine/VertexTensors.h"

#include <Eigen/LU>

namespace aniso::refine3d {

void VertexTensorTable::renumber(const std::vector<std::uint32_t>& newVertex) {
  std::vector<double> s(scale.size(), 1.0);
  std::vector<std::uint32_t> i(index.size(), 0);
  for (std::size_t v = 0; v < scale.size() && v < newVertex.size(); ++v) {
    s[newVertex[v]] = scale[v];
    i[newVertex[v]] = index[v];
  }
  scale = std::move(s);
  index = std::move(i);
}

void VertexTensors::store(std::size_t v, const Mat3& m) {
  const double s = isotropicScale(m);
  if (s > 0) {
    t_.scale[v] = s;
    return;
  }
  t_.scale[v] = 0;
  t_.index[v] = static_cast<std::uint32_t>(t_.aniso.size());
  t_.aniso.push_back(m);
}

void VertexTensors::sync() {
  const std::size_t old = t_.scale.size();
  t_.scale.resize(mesh_.numVertices(), 1.0);
  t_.index.resize(mesh_.numVertices(), 0);
  for (std::size_t v = old; v < t_.scale.size(); ++v) {
    const del3d::VertexId id(static_cast<std::uint32_t>(v));
    if (mesh_.vertexTet(id).valid()) store(v, cs_.getMetric(mesh_.point(id)).matrix());
  }
}

void VertexTensors::add(del3d::VertexId v, const Mat3& m) {
  if (t_.scale.size() <= v.index) {
    t_.scale.resize(std::size_t{v.index} + 1, 1.0);
    t_.index.resize(t_.scale.size(), 0);
  }
  store(v.index, m);
}

Mat3 VertexTensors::tetMetric(const std::uint32_t* v) const {
  return 0.25 * (at(del3d::VertexId(v[0])) + at(del3d::VertexId(v[1])) + at(del3d::VertexId(v[2])) +
                 at(del3d::VertexId(v[3])));
}

Mat3 VertexTensors::tetLengthMetric(const std::uint32_t* v) const {
  double s;
  if (tetLengthScale(v, s)) return s * Mat3::Identity();
  Mat3 lengths = Mat3::Zero();
  for (int i = 0; i < 4; ++i) lengths += at(del3d::VertexId(v[i])).inverse();
  return (0.25 * lengths).inverse();
}

Mat3 VertexTensors::edgeLengthMetric(del3d::VertexId a, del3d::VertexId b) const {
  const double sa = scale(a), sb = scale(b);
  if (sa > 0 && sb > 0) return edgeLengthScale(sa, sb) * Mat3::Identity();
  return (0.5 * (at(a).inverse() + at(b).inverse())).inverse();
}

std::size_t VertexTensors::memoryBytes() const {
  return t_.scale.capacity() * sizeof(double) + t_.index.capacity() * sizeof(std::uint32_t) +
         t_.aniso.capacity() * sizeof(Mat3);
}

}  // namespace aniso::refine3d
