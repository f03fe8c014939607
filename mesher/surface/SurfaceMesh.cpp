// SurfaceMesh::validate and edgeCounts (see SurfaceMesh.h). Sorting, not hashing, so the
// messages come out in a deterministic order.
#include "mesher/surface/SurfaceMesh.h"

#include "mesher/core/NodeBuckets.h"

#include <algorithm>
#include <span>
#include <sstream>
#include <tuple>

namespace aniso {
namespace {

struct EdgeKey {
  int a = 0, b = 0;    ///< a < b
  int tri = 0;
  bool forward = true; ///< the triangle runs a → b
  int face = 0;
};

std::vector<EdgeKey> triangleEdges(const SurfaceMesh& m) {
  std::vector<EdgeKey> keys;
  keys.reserve(3 * m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const std::array<int, 3>& tr = m.triangles[t];
    const int face = t < m.triangleFace.size() ? m.triangleFace[t] : -1;
    for (int k = 0; k < 3; ++k) {
      const int p = tr[k], q = tr[(k + 1) % 3];
      keys.push_back({std::min(p, q), std::max(p, q), static_cast<int>(t), p < q, face});
    }
  }
  // Quads count as elements numbered after the triangles.
  for (std::size_t i = 0; i < m.quads.size(); ++i) {
    const std::array<int, 4>& qu = m.quads[i];
    const int face = i < m.quadFace.size() ? m.quadFace[i] : -1;
    for (int k = 0; k < 4; ++k) {
      const int p = qu[k], q = qu[(k + 1) % 4];
      keys.push_back({std::min(p, q), std::max(p, q), static_cast<int>(m.triangles.size() + i), p < q, face});
    }
  }
  return keys;
}

std::string triangleName(std::size_t t) { return "triangle " + std::to_string(t); }

}  // namespace

std::vector<std::string> SurfaceMesh::validate() const {
  std::vector<std::string> out;
  if (nodeOn.size() != nodes.size())
    out.push_back(std::to_string(nodes.size()) + " nodes but " + std::to_string(nodeOn.size()) + " node entities");
  if (triangleFace.size() != triangles.size())
    out.push_back(std::to_string(triangles.size()) + " triangles but " + std::to_string(triangleFace.size()) +
                  " triangle faces");
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (!nodes[i].allFinite()) out.push_back("node " + std::to_string(i) + " has non-finite coordinates");

  const int n = static_cast<int>(nodes.size());
  bool indicesOk = true;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const std::array<int, 3>& tr = triangles[t];
    if (std::any_of(tr.begin(), tr.end(), [n](int v) { return v < 0 || v >= n; })) {
      out.push_back(triangleName(t) + " refers to a node out of range");
      indicesOk = false;
    } else if (tr[0] == tr[1] || tr[1] == tr[2] || tr[2] == tr[0]) {
      out.push_back(triangleName(t) + " repeats node " + std::to_string(tr[0] == tr[1] || tr[0] == tr[2] ? tr[0] : tr[1]));
    }
  }
  if (!indicesOk) return out;

  // Same three nodes twice.
  std::vector<std::pair<std::array<int, 3>, int>> sorted;
  sorted.reserve(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    std::array<int, 3> s = triangles[t];
    std::sort(s.begin(), s.end());
    sorted.push_back({s, static_cast<int>(t)});
  }
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i].first == sorted[i - 1].first)
      out.push_back(triangleName(sorted[i].second) + " has the same nodes as " + triangleName(sorted[i - 1].second));

  // An edge in more than two triangles of one face.
  std::vector<EdgeKey> keys = triangleEdges(*this);
  std::sort(keys.begin(), keys.end(), [](const EdgeKey& x, const EdgeKey& y) {
    return std::tie(x.face, x.a, x.b, x.tri) < std::tie(y.face, y.a, y.b, y.tri);
  });
  for (std::size_t i = 0; i < keys.size();) {
    std::size_t j = i;
    while (j < keys.size() && keys[j].face == keys[i].face && keys[j].a == keys[i].a && keys[j].b == keys[i].b) ++j;
    if (j - i > 2) {
      std::ostringstream s;
      s << "edge (" << keys[i].a << ", " << keys[i].b << ") is used by " << j - i << " triangles of face "
        << keys[i].face + 1;
      out.push_back(s.str());
    }
    i = j;
  }
  return out;
}

SurfaceMesh::EdgeCounts SurfaceMesh::edgeCounts() const {
  const std::vector<EdgeKey> keys = triangleEdges(*this);
  int lowest = 0, highest = -1;
  for (const EdgeKey& k : keys) lowest = std::min(lowest, k.a), highest = std::max(highest, k.b);
  EdgeCounts c;
  auto count = [&c](std::span<EdgeKey> uses) {  // sorted by (a, b, tri)
    for (std::size_t i = 0; i < uses.size();) {
      std::size_t j = i;
      while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b) ++j;
      const std::size_t n = j - i;
      if (n == 1) ++c.open;
      else if (n > 2) ++c.nonManifold;
      else if (uses[i].forward == uses[i + 1].forward) ++c.misoriented;
      i = j;
    }
  };
  auto byEnds = [](const EdgeKey& x, const EdgeKey& y) { return std::tie(x.a, x.b, x.tri) < std::tie(y.a, y.b, y.tri); };
  if (lowest < 0) {  // an invalid node index (validate() names it): one sort of every use
    std::vector<EdgeKey> all = keys;
    std::sort(all.begin(), all.end(), byEnds);
    count(all);
    return c;
  }
  // the uses bucketed by their smaller end (linear), each bucket sorted (NodeBuckets.h)
  NodeBuckets<EdgeKey> byNode = bucketByNode(std::span<const EdgeKey>(keys), static_cast<std::size_t>(highest) + 1,
                                             [](const EdgeKey& k) { return k.a; });
  for (std::size_t a = 0; a < byNode.nodes(); ++a) {
    const std::span<EdgeKey> bucket = byNode.bucket(a);
    std::sort(bucket.begin(), bucket.end(), byEnds);
    count(bucket);
  }
  return c;
}

}  // namespace aniso
