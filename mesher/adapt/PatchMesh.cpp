#include "mesher/adapt/PatchMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include <Eigen/Geometry>

namespace aniso {

std::vector<std::vector<int>> nodeNeighbours(const PatchMesh& m) {
  std::vector<std::vector<int>> out(m.nodes.size());
  for (std::size_t c = 0; c < m.cellCount(); ++c)
    for (int a = m.offsets[c]; a < m.offsets[c + 1]; ++a)
      for (int b = m.offsets[c]; b < m.offsets[c + 1]; ++b)
        if (a != b) out[m.conn[a]].push_back(m.conn[b]);
  for (auto& n : out) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  return out;
}

namespace {

/// Facets by their sorted corners (dim 2: −1 first) -> (how many cells have it, the last one).
std::map<std::array<int, 3>, std::pair<int, int>> facetCounts(const PatchMesh& m) {
  std::map<std::array<int, 3>, std::pair<int, int>> facets;
  const int k = m.corners();
  for (std::size_t c = 0; c < m.cellCount(); ++c) {
    const int* v = m.conn.data() + m.offsets[c];
    for (int skip = 0; skip < k; ++skip) {
      std::array<int, 3> f{-1, -1, -1};
      int n = 0;
      for (int i = 0; i < k; ++i)
        if (i != skip) f[n++] = v[i];
      std::sort(f.begin(), f.end());
      auto& e = facets[f];
      ++e.first;
      e.second = static_cast<int>(c);
    }
  }
  return facets;
}

}  // namespace

std::vector<char> boundaryNodes(const PatchMesh& m) {
  std::vector<char> out(m.nodes.size(), 0);
  const int k = m.corners();
  for (const auto& [f, e] : facetCounts(m)) {
    if (e.first != 1) continue;
    for (int v : f)
      if (v >= 0) out[v] = 1;
    // the cell's other (mid-side) nodes: mark all of them, a quadratic boundary cell's
    // interior mid-edge nodes too (they only get a larger patch)
    for (int a = m.offsets[e.second] + k; a < m.offsets[e.second + 1]; ++a) out[m.conn[a]] = 1;
  }
  return out;
}

std::vector<BoundaryFacet> boundaryFacets(const PatchMesh& m) {
  std::vector<BoundaryFacet> out;
  for (const auto& [f, e] : facetCounts(m)) {
    if (e.first != 1) continue;
    BoundaryFacet b;
    if (m.dim == 3) {
      b.nodes = f;
      const Vec3 n = (m.nodes[f[1]] - m.nodes[f[0]]).cross(m.nodes[f[2]] - m.nodes[f[0]]);
      b.measure = 0.5 * n.norm();
      b.direction = b.measure > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    } else {
      b.nodes = {f[1], f[2], -1};
      const Vec3 t = m.nodes[f[2]] - m.nodes[f[1]];
      b.measure = t.norm();
      b.direction = b.measure > 0 ? Vec3(t / b.measure) : Vec3::Zero();
    }
    if (b.measure > 0) out.push_back(b);
  }
  return out;
}

double cellMeasure(const PatchMesh& m, std::size_t c) {
  const int* v = m.conn.data() + m.offsets[c];
  const Vec3 a = m.nodes[v[1]] - m.nodes[v[0]], b = m.nodes[v[2]] - m.nodes[v[0]];
  if (m.dim == 2) return 0.5 * a.cross(b).norm();
  return std::abs(a.cross(b).dot(m.nodes[v[3]] - m.nodes[v[0]])) / 6.0;
}

std::vector<double> nodeMeasures(const PatchMesh& m) {
  std::vector<double> out(m.nodes.size(), 0.0);
  const int k = m.corners();
  for (std::size_t c = 0; c < m.cellCount(); ++c) {
    const double share = cellMeasure(m, c) / k;
    for (int i = 0; i < k; ++i) out[m.conn[m.offsets[c] + i]] += share;
  }
  return out;
}

void tangentFrame(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Vec3 a = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  t1 = n.cross(a).normalized();
  t2 = n.cross(t1);
}

std::vector<Vec3> nodeNormals(const PatchMesh& m) {
  if (m.dim != 2) return {};
  std::vector<Vec3> out(m.nodes.size(), Vec3::Zero());
  for (std::size_t c = 0; c < m.cellCount(); ++c) {
    const int* v = m.conn.data() + m.offsets[c];
    const Vec3 n = (m.nodes[v[1]] - m.nodes[v[0]]).cross(m.nodes[v[2]] - m.nodes[v[0]]);
    for (int a = m.offsets[c]; a < m.offsets[c + 1]; ++a) out[m.conn[a]] += n;
  }
  for (Vec3& n : out) {
    const double l = n.norm();
    n = l > 0 ? Vec3(n / l) : Vec3::Zero();
  }
  return out;
}

}  // namespace aniso
