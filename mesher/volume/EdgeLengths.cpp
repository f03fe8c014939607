#include "mesher/volume/EdgeLengths.h"

#include <algorithm>
#include <array>
#include <span>
#include <utility>
#include <vector>

namespace aniso {
namespace {

using Edge = std::pair<int, int>;

void addCycle(std::span<const int> v, std::vector<Edge>& out) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    const int a = v[i], b = v[(i + 1) % v.size()];
    out.emplace_back(std::min(a, b), std::max(a, b));
  }
}

EdgeLengthRange measure(std::vector<Edge>& edges, const std::vector<Vec3>& nodes) {
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  EdgeLengthRange r;
  double sum = 0;
  for (const auto& [a, b] : edges) {
    if (a < 0 || b >= static_cast<int>(nodes.size()) || a == b) continue;
    const double l = (nodes[static_cast<std::size_t>(a)] - nodes[static_cast<std::size_t>(b)]).norm();
    r.min = r.edges ? std::min(r.min, l) : l;
    r.max = std::max(r.max, l);
    sum += l;
    ++r.edges;
  }
  r.mean = r.edges ? sum / static_cast<double>(r.edges) : 0.0;
  return r;
}

}  // namespace

EdgeLengthRange edgeLengths(const SurfaceMesh& mesh) {
  std::vector<Edge> edges;
  edges.reserve(3 * mesh.triangles.size() + 4 * mesh.quads.size());
  for (const auto& t : mesh.triangles) addCycle(t, edges);
  for (const auto& q : mesh.quads) addCycle(q, edges);
  return measure(edges, mesh.nodes);
}

EdgeLengthRange edgeLengths(const VolumeMesh& mesh) {
  std::vector<Edge> edges;
  edges.reserve(6 * mesh.tets.size());
  for (const auto& t : mesh.tets)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) edges.emplace_back(std::min(t[i], t[j]), std::max(t[i], t[j]));
  return measure(edges, mesh.nodes());
}

}  // namespace aniso
