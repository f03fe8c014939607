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

/// Each distinct edge once, in increasing (a, b) order: the edges bucketed by their smaller
/// end (a counting sort, linear), each bucket's other ends sorted and made unique (a few
/// per node): a global sort of all edge uses took a tenth of a whole run on a cube of half a
/// million tets.
EdgeLengthRange measure(const std::vector<Edge>& edges, const std::vector<Vec3>& nodes) {
  const std::size_t n = nodes.size();
  std::vector<std::size_t> start(n + 2, 0);
  for (const auto& [a, b] : edges)
    if (a >= 0 && b < static_cast<int>(n) && a != b) ++start[static_cast<std::size_t>(a) + 2];
  for (std::size_t i = 2; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<int> other(start.back());
  for (const auto& [a, b] : edges)
    if (a >= 0 && b < static_cast<int>(n) && a != b) other[start[static_cast<std::size_t>(a) + 1]++] = b;
  EdgeLengthRange r;
  double sum = 0;
  for (std::size_t a = 0; a < n; ++a) {
    const auto first = other.begin() + static_cast<std::ptrdiff_t>(start[a]);
    const auto last = other.begin() + static_cast<std::ptrdiff_t>(start[a + 1]);
    std::sort(first, last);
    for (auto it = first; it != last; ++it) {
      if (it != first && *it == *(it - 1)) continue;
      const double l = (nodes[a] - nodes[static_cast<std::size_t>(*it)]).norm();
      r.min = r.edges ? std::min(r.min, l) : l;
      r.max = std::max(r.max, l);
      sum += l;
      ++r.edges;
    }
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
