#include "mesher/control/BackgroundMeshGraph.h"

#include <algorithm>
#include <string>

#include "mesher/core/Error.h"
#include "mesher/metric/MetricGradation.h"
#include "mesher/metric/MetricInterpolation.h"
#include "mesher/metric/SymmetricEigen.h"

namespace aniso {
namespace {

/// Relative change of an eigenvalue that counts as a change of a smoothed metric (as in
/// TreeControlSpace).
constexpr double kGradationChangeTolerance = 1e-9;

}  // namespace

VertexGraph makeVertexGraph(int vertexCount, std::vector<std::array<int, 2>> pairs) {
  // Counting sort by the smaller end, then a sort of each (short) bucket by the other:
  // linear in the number of pairs up to the vertex degree, where one global sort of the
  // 6 pairs per tetrahedron dominated the smoothing of large 3D meshes.
  std::vector<int> first(vertexCount + 1, 0);
  for (auto& p : pairs) {
    if (p[0] > p[1]) std::swap(p[0], p[1]);
    ++first[p[0] + 1];
  }
  for (int v = 0; v < vertexCount; ++v) first[v + 1] += first[v];
  std::vector<int> other(pairs.size());
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (const auto& p : pairs) other[fill[p[0]]++] = p[1];
  }
  VertexGraph g;
  g.edges.reserve(pairs.size() / 2 + 1);
  for (int a = 0; a < vertexCount; ++a) {
    const auto begin = other.begin() + first[a], end = other.begin() + first[a + 1];
    std::sort(begin, end);
    for (auto it = begin; it != end; ++it)
      if (it == begin || *it != *(it - 1)) g.edges.push_back({a, *it});
  }
  g.start.assign(vertexCount + 1, 0);
  for (const auto& e : g.edges) {
    ++g.start[e[0] + 1];
    ++g.start[e[1] + 1];
  }
  for (int v = 0; v < vertexCount; ++v) g.start[v + 1] += g.start[v];
  g.incident.resize(2 * g.edges.size());
  std::vector<int> fill(g.start.begin(), g.start.end() - 1);
  for (int e = 0; e < static_cast<int>(g.edges.size()); ++e) {
    g.incident[fill[g.edges[e][0]]++] = e;
    g.incident[fill[g.edges[e][1]]++] = e;
  }
  return g;
}

template <int D>
void extrapolateLayers(const VertexGraph& g, const std::vector<double>& edgeLength, std::vector<std::uint8_t>& known,
                       std::vector<Metric<D>>& metric) {
  const int nv = static_cast<int>(g.vertexCount());
  std::vector<int> front;
  for (;;) {
    front.clear();
    for (int v = 0; v < nv; ++v) {
      if (known[v]) continue;
      for (int j = g.start[v]; j < g.start[v + 1]; ++j)
        if (known[g.other(g.incident[j], v)]) {
          front.push_back(v);
          break;
        }
    }
    if (front.empty()) break;
    for (int v : front) {
      MetricBlend<D> b;
      for (int j = g.start[v]; j < g.start[v + 1]; ++j) {
        const int e = g.incident[j], w = g.other(e, v);
        if (known[w]) b.add(metric[w], 1 / edgeLength[e]);
      }
      metric[v] = b.result();
    }
    for (int v : front) known[v] = 1;
  }
  if (std::find(known.begin(), known.end(), 0) != known.end())
    throw MeshingError("background mesh: extrapolation did not reach every control vertex");
}

template <int D>
int smoothByEdgeMarking(const VertexGraph& g, const std::vector<Eigen::Matrix<double, D, 1>>& edgeVector,
                        double gamma, std::vector<Metric<D>>& metric, std::vector<std::uint8_t>& changed) {
  using Mat = Eigen::Matrix<double, D, D>;
  gradationSlopeLimit(gamma);  // throws for an invalid γ_M
  const GradationRule rule{gamma, 0.0, kGradationChangeTolerance};
  const int ne = static_cast<int>(g.edges.size());
  std::vector<int> current(ne), next;
  for (int e = 0; e < ne; ++e) current[e] = e;
  std::vector<std::uint8_t> queued(ne, 0);
  // Cheap exact test that a pair is already graded (see TreeControlSpace::smoothGradation):
  // with T = M² and s of eq. 2.30, nothing changes when s² T_a − T_b and s² T_b − T_a are
  // positive definite.
  std::vector<Mat> tensor(metric.size());
  for (std::size_t v = 0; v < metric.size(); ++v) tensor[v] = metric[v].tensor();
  for (int round = 1; round <= kMaxSmoothingRounds; ++round) {
    for (int e : current) queued[e] = 0;
    next.clear();
    for (int e : current) {
      const int a = g.edges[e][0], b = g.edges[e][1];
      const auto& d = edgeVector[e];
      const double dR = d.norm();
      if (dR > 0) {
        const double f = gradationFactor(metric[a].lengthAlong(d), metric[b].lengthAlong(d), dR, gamma);
        const double f2 = f * f;
        if (isSymmetricPositiveDefinite(Mat(f2 * tensor[a] - tensor[b])) &&
            isSymmetricPositiveDefinite(Mat(f2 * tensor[b] - tensor[a])))
          continue;
      }
      const Mat before[2] = {metric[a].matrix(), metric[b].matrix()};
      if (!aniso::smoothGradation<D>(metric[a], metric[b], d, rule)) continue;
      for (int k = 0; k < 2; ++k) {
        const int v = g.edges[e][k];
        if (metric[v].matrix() == before[k]) continue;
        changed[v] = 1;
        tensor[v] = metric[v].tensor();
        for (int j = g.start[v]; j < g.start[v + 1]; ++j) {
          const int f = g.incident[j];
          if (!queued[f]) {
            queued[f] = 1;
            next.push_back(f);
          }
        }
      }
    }
    if (next.empty()) return round;
    std::swap(current, next);
  }
  throw MeshingError("background mesh: gradation smoothing did not converge in " +
                     std::to_string(kMaxSmoothingRounds) + " rounds");
}

template void extrapolateLayers<2>(const VertexGraph&, const std::vector<double>&, std::vector<std::uint8_t>&,
                                   std::vector<Metric<2>>&);
template void extrapolateLayers<3>(const VertexGraph&, const std::vector<double>&, std::vector<std::uint8_t>&,
                                   std::vector<Metric<3>>&);
template int smoothByEdgeMarking<2>(const VertexGraph&, const std::vector<Vec2>&, double, std::vector<Metric<2>>&,
                                    std::vector<std::uint8_t>&);
template int smoothByEdgeMarking<3>(const VertexGraph&, const std::vector<Vec3>&, double, std::vector<Metric<3>>&,
                                    std::vector<std::uint8_t>&);

}  // namespace aniso
