#include "mesher/highorder/CurvedVolume.h"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "mesher/surface/MidEdgeGeometry.h"

namespace aniso {
namespace {

std::uint64_t edgeKey(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(a < b ? a : b), hi = static_cast<std::uint32_t>(a < b ? b : a);
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

/// A key of the unordered triangle and its orientation relative to the sorted order.
struct TriangleKey {
  std::array<int, 3> sorted;
  bool even;  ///< (a, b, c) is an even permutation of sorted
};

TriangleKey triangleKey(int a, int b, int c) {
  std::array<int, 3> s{a, b, c};
  bool even = true;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2 - i; ++j)
      if (s[j] > s[j + 1]) {
        std::swap(s[j], s[j + 1]);
        even = !even;
      }
  return {s, even};
}

struct ArrayHash {
  std::size_t operator()(const std::array<int, 3>& a) const {
    std::uint64_t h = 1469598103934665603ull;
    for (int v : a) h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

}  // namespace

std::vector<double> curvedSolidVolumes(const Model& model, const VolumeMesh& mesh, const std::vector<char>& which) {
  const std::size_t nSolids = model.solids.size();
  std::vector<double> out(nSolids, 0.0);
  auto wanted = [&](int s) {
    return s >= 0 && static_cast<std::size_t>(s) < nSolids && (which.empty() || which[static_cast<std::size_t>(s)]);
  };
  const SurfaceMesh& surface = mesh.surface;
  const std::vector<Vec3>& x = surface.nodes;
  std::unordered_map<std::array<int, 3>, int, ArrayHash> triangles;
  triangles.reserve(surface.triangles.size());
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    const auto& tri = surface.triangles[t];
    triangles.emplace(triangleKey(tri[0], tri[1], tri[2]).sorted, static_cast<int>(t));
  }
  const MidEdgeGeometry geometry(model, surface);
  std::unordered_map<std::uint64_t, Vec3> offset;  // mid node − chord midpoint, per mesh edge
  // per boundary triangle, in its own orientation; NaN until computed
  std::vector<double> bulge(surface.triangles.size(), std::numeric_limits<double>::quiet_NaN());
  auto bulgeOf = [&](int t) {
    if (!std::isnan(bulge[static_cast<std::size_t>(t)])) return bulge[static_cast<std::size_t>(t)];
    const auto& tri = surface.triangles[static_cast<std::size_t>(t)];
    const int face = surface.triangleFace[static_cast<std::size_t>(t)];
    const Vec3 n2 = (x[tri[1]] - x[tri[0]]).cross(x[tri[2]] - x[tri[0]]);  // 2A · unit normal
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      auto [it, inserted] = offset.try_emplace(edgeKey(a, b));
      if (inserted) it->second = geometry.place(a, b, face).p - 0.5 * (x[a] + x[b]);
      sum += it->second.dot(n2);
    }
    const double v = sum / 6;  // A/3 · Σ d_k with A = |n2|/2 and d_k = offset · n2/|n2|
    bulge[static_cast<std::size_t>(t)] = v;
    return v;
  };
  // Outward faces of a positively oriented tetrahedron.
  static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const int s = mesh.tetSolid[t];
    if (!wanted(s)) continue;
    const auto& tet = mesh.tets[t];
    const Vec3 &p0 = x[tet[0]], &p1 = x[tet[1]], &p2 = x[tet[2]], &p3 = x[tet[3]];
    double v = (p1 - p0).dot((p2 - p0).cross(p3 - p0)) / 6;
    for (const auto& f : kFaces) {
      const TriangleKey key = triangleKey(tet[f[0]], tet[f[1]], tet[f[2]]);
      const auto found = triangles.find(key.sorted);
      if (found == triangles.end()) continue;
      const auto& tri = surface.triangles[static_cast<std::size_t>(found->second)];
      const bool sameAsTriangle = triangleKey(tri[0], tri[1], tri[2]).even == key.even;
      v += (sameAsTriangle ? 1 : -1) * bulgeOf(found->second);
    }
    out[static_cast<std::size_t>(s)] += v;
  }
  return out;
}

}  // namespace aniso
