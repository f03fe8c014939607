#include "mesher/volume/SolidMeshCache.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace aniso {
namespace {

/// Two independent 64-bit lanes (splitmix64 finaliser on a running state; a multiply-xor
/// polynomial): a 128-bit key whose accidental equality is out of reach.
class Hasher {
 public:
  void add(std::uint64_t x) {
    a_ = mix(a_ ^ (x + 0x9e3779b97f4a7c15ULL));
    b_ = (b_ ^ x) * 0x100000001b3ULL + (x >> 29) + 0x632be59bd9b4e019ULL;
  }
  void add(double d) { add(std::bit_cast<std::uint64_t>(d)); }
  void add(int v) { add(static_cast<std::uint64_t>(static_cast<std::uint32_t>(v))); }
  std::array<std::uint64_t, 2> value() const { return {a_, mix(b_)}; }

 private:
  static std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::uint64_t a_ = 0x243f6a8885a308d3ULL, b_ = 0x13198a2e03707344ULL;
};

int rank(const std::vector<int>& nodes, int v) {
  return static_cast<int>(std::lower_bound(nodes.begin(), nodes.end(), v) - nodes.begin());
}

}  // namespace

SolidBoundaryKey solidBoundaryKey(const Model& model, const SurfaceMesh& surface,
                                  const std::vector<std::vector<int>>& faceTriangles, int solid) {
  SolidBoundaryKey key;
  const std::vector<int> faces = model.solidBoundaryFaces(solid);
  for (const int f : faces)
    if (f >= 0 && static_cast<std::size_t>(f) < faceTriangles.size())
      for (const int t : faceTriangles[static_cast<std::size_t>(f)])
        for (const int v : surface.triangles[static_cast<std::size_t>(t)]) key.nodes.push_back(v);
  std::sort(key.nodes.begin(), key.nodes.end());
  key.nodes.erase(std::unique(key.nodes.begin(), key.nodes.end()), key.nodes.end());
  Hasher h;
  for (const int f : faces) {
    h.add(f);
    if (f < 0 || static_cast<std::size_t>(f) >= faceTriangles.size()) continue;
    const std::vector<int>& ts = faceTriangles[static_cast<std::size_t>(f)];
    h.add(static_cast<std::uint64_t>(ts.size()));
    key.triangles += ts.size();
    for (const int t : ts)
      for (const int v : surface.triangles[static_cast<std::size_t>(t)]) h.add(rank(key.nodes, v));
  }
  for (const int v : key.nodes) {
    const Vec3& x = surface.nodes[static_cast<std::size_t>(v)];
    const NodeOn& on = surface.nodeOn[static_cast<std::size_t>(v)];
    h.add(x.x()), h.add(x.y()), h.add(x.z());
    h.add(static_cast<int>(on.kind)), h.add(on.entity), h.add(on.t), h.add(on.uv.x()), h.add(on.uv.y());
  }
  key.hash = h.value();
  return key;
}

std::optional<SolidPiece> SolidMeshCache::find(int solid, const SolidBoundaryKey& key) const {
  const Entry& e = entries_.at(static_cast<std::size_t>(solid));
  if (!e.valid || !(e.key == key)) return std::nullopt;
  SolidPiece p = e.piece;
  for (auto& q : p.tets)
    for (int& v : q)
      if (v >= 0) v = key.nodes[static_cast<std::size_t>(v)];
  return p;
}

void SolidMeshCache::store(int solid, const SolidBoundaryKey& key, const SolidPiece& piece) {
  Entry& e = entries_.at(static_cast<std::size_t>(solid));
  e.valid = piece.complete && piece.missing.empty() && piece.outcome.status == SolidOutcome::Status::Ok &&
            piece.outcome.problems.empty();
  if (!e.valid) {
    e.piece = SolidPiece{};
    return;
  }
  e.key = key;
  e.piece = piece;
  for (auto& q : e.piece.tets)
    for (int& v : q)
      if (v >= 0) v = rank(key.nodes, v);
}

}  // namespace aniso
