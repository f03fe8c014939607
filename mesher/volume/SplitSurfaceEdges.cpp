#include "mesher/volume/SplitSurfaceEdges.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <unordered_set>
#include <vector>

#include "mesher/core/Error.h"
#include "mesher/surface/MidEdgeGeometry.h"

namespace aniso {
namespace {

std::uint64_t edgeKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

/// A point's coordinates, bit for bit (two nodes at one point are one vertex to the
/// Delaunay kernel: a solid with them cannot be meshed).
struct PointKey {
  std::array<std::uint64_t, 3> bits;
  explicit PointKey(const Vec3& p) {
    for (int k = 0; k < 3; ++k) {
      const double x = p[k] == 0 ? 0.0 : p[k];  // -0 and +0 alike
      std::memcpy(&bits[static_cast<std::size_t>(k)], &x, sizeof x);
    }
  }
  bool operator==(const PointKey& o) const { return bits == o.bits; }
};
struct PointKeyHash {
  std::size_t operator()(const PointKey& k) const {
    return std::hash<std::uint64_t>()(k.bits[0] ^ (k.bits[1] * 0x9E3779B97F4A7C15ull) ^ (k.bits[2] * 0xC2B2AE3D27D4EB4Full));
  }
};

}  // namespace

std::array<int, 2> longestEdge(const SurfaceMesh& mesh, const std::array<int, 3>& t) {
  int best = 0;
  double bestLen = -1;
  for (int k = 0; k < 3; ++k) {
    const double len = (mesh.nodes[t[(k + 1) % 3]] - mesh.nodes[t[k]]).squaredNorm();
    if (len > bestLen) {
      bestLen = len;
      best = k;
    }
  }
  return {t[best], t[(best + 1) % 3]};
}

SplitStats splitSurfaceEdges(const Model& model, SurfaceMesh& mesh, std::span<const std::array<int, 2>> edges) {
  if (!mesh.triangleMid.empty() || !mesh.quadMid.empty())
    throw MeshingError("splitSurfaceEdges: the surface mesh is quadratic already");
  SplitStats stats;
  stats.trianglesBefore = static_cast<int>(mesh.triangles.size());
  // The requested edges that are edges of triangles, in a deterministic order.
  std::vector<std::uint64_t> wanted;
  wanted.reserve(edges.size());
  for (const auto& e : edges)
    if (e[0] != e[1]) wanted.push_back(edgeKey(e[0], e[1]));
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  // First triangle (hence face) of each wanted edge; -1 when no triangle has it.
  std::vector<int> firstTri(wanted.size(), -1);
  auto find = [&](std::uint64_t key) {
    const auto it = std::lower_bound(wanted.begin(), wanted.end(), key);
    return it != wanted.end() && *it == key ? static_cast<int>(it - wanted.begin()) : -1;
  };
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tr = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int w = find(edgeKey(tr[k], tr[(k + 1) % 3]));
      if (w >= 0 && firstTri[w] < 0) firstTri[w] = static_cast<int>(t);
    }
  }
  // New nodes, placed with the geometry indexed before any change.
  std::vector<int> midOf(wanted.size(), -1);
  {
    const MidEdgeGeometry geometry(model, mesh);
    std::vector<MidNode> placed(wanted.size());
    for (std::size_t w = 0; w < wanted.size(); ++w) {
      if (firstTri[w] < 0) continue;
      const int a = static_cast<int>(wanted[w] >> 32), b = static_cast<int>(wanted[w] & 0xFFFFFFFFu);
      placed[w] = geometry.place(a, b, mesh.triangleFace[firstTri[w]]);
    }
    // a middle placed on a node already there (two edges of a fold over one point of
    // the CAD) is not added: the edge stays whole
    std::unordered_set<PointKey, PointKeyHash> taken;
    taken.reserve(mesh.nodes.size() + wanted.size());
    for (const Vec3& p : mesh.nodes) taken.insert(PointKey(p));
    for (std::size_t w = 0; w < wanted.size(); ++w) {
      if (firstTri[w] < 0 || !taken.insert(PointKey(placed[w].p)).second) continue;
      midOf[w] = mesh.addNode(placed[w].p, placed[w].on);
      ++stats.edgesSplit;
    }
  }
  // Triangles: each split edge k of (n0, n1, n2) gets its mid node m_k; the triangle is
  // cut into the corner triangles at the split edges plus what remains.
  std::vector<std::array<int, 3>> tris;
  std::vector<int> faces;
  tris.reserve(mesh.triangles.size() + 2 * static_cast<std::size_t>(stats.edgesSplit));
  faces.reserve(tris.capacity());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto n = mesh.triangles[t];
    const int f = mesh.triangleFace[t];
    int m[3];
    int count = 0;
    for (int k = 0; k < 3; ++k) {
      const int w = find(edgeKey(n[k], n[(k + 1) % 3]));
      m[k] = w >= 0 ? midOf[w] : -1;
      count += m[k] >= 0;
    }
    auto add = [&](int a, int b, int c) {
      tris.push_back({a, b, c});
      faces.push_back(f);
    };
    if (count == 0) {
      add(n[0], n[1], n[2]);
    } else if (count == 3) {
      add(n[0], m[0], m[2]);
      add(m[0], n[1], m[1]);
      add(m[2], m[1], n[2]);
      add(m[0], m[1], m[2]);
    } else if (count == 1) {
      const int k = m[0] >= 0 ? 0 : m[1] >= 0 ? 1 : 2;  // split edge (n_k, n_k+1), apex n_k+2
      add(n[k], m[k], n[(k + 2) % 3]);
      add(m[k], n[(k + 1) % 3], n[(k + 2) % 3]);
    } else {
      const int k = m[0] < 0 ? 0 : m[1] < 0 ? 1 : 2;  // the edge (n_k, n_k+1) not split
      const int a = n[k], b = n[(k + 1) % 3], c = n[(k + 2) % 3];
      const int mbc = m[(k + 1) % 3], mca = m[(k + 2) % 3];
      add(mca, mbc, c);  // corner at c
      // The quadrilateral (a, b, mbc, mca): cut along its shorter diagonal.
      const Vec3& pa = mesh.nodes[a];
      const Vec3& pb = mesh.nodes[b];
      if ((mesh.nodes[mbc] - pa).squaredNorm() <= (mesh.nodes[mca] - pb).squaredNorm()) {
        add(a, b, mbc);
        add(a, mbc, mca);
      } else {
        add(a, b, mca);
        add(b, mbc, mca);
      }
    }
  }
  mesh.triangles = std::move(tris);
  mesh.triangleFace = std::move(faces);
  stats.trianglesAfter = static_cast<int>(mesh.triangles.size());
  return stats;
}

}  // namespace aniso
