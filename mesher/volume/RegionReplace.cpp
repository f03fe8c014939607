#include "mesher/volume/RegionReplace.h"

#include <algorithm>
#include <map>
#include <unordered_set>

namespace aniso::volume {

using del3d::kNone;
using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

namespace {

using Key = std::array<std::uint32_t, 3>;

Key faceKey(const std::uint32_t* v, int i) {
  Key k = {v[del3d::kFaceVertex[i][0]], v[del3d::kFaceVertex[i][1]], v[del3d::kFaceVertex[i][2]]};
  std::sort(k.begin(), k.end());
  return k;
}

struct FaceSlot {
  std::uint32_t outerCode = kNone;  ///< neighbour code across an old boundary face
  bool outer = false, constrained = false;
  int uses = 0;                     ///< new faces on this key
  std::uint32_t first = kNone;      ///< 4k + j of the first new face
  std::uint32_t second = kNone;
};

}  // namespace

bool replaceRegion(TetMesh& mesh, std::span<const TetId> oldTets, std::span<const std::array<VertexId, 4>> newTets,
                   std::vector<TetId>* out) {
  std::unordered_set<std::uint32_t> old;
  for (const TetId t : oldTets) old.insert(t.index);
  std::map<Key, FaceSlot> faces;
  for (const TetId t : oldTets) {
    for (int i = 0; i < 4; ++i) {
      const TetId n = mesh.neighbour(t, i);
      if (n.valid() && old.count(n.index)) continue;
      FaceSlot& s = faces[faceKey(mesh.tetVertices(t), i)];
      if (s.outer) return false;  // the same face twice on the boundary: not a polyhedron
      s.outer = true;
      s.outerCode = mesh.adjacentCode(t, i);
      s.constrained = mesh.isConstrained(t, i);
    }
  }
  for (std::size_t k = 0; k < newTets.size(); ++k) {
    std::uint32_t raw[4];
    for (int m = 0; m < 4; ++m) raw[m] = newTets[k][m].index;
    for (int j = 0; j < 4; ++j) {
      FaceSlot& s = faces[faceKey(raw, j)];
      const std::uint32_t code = static_cast<std::uint32_t>(4 * k + j);
      (s.uses == 0 ? s.first : s.second) = code;
      ++s.uses;
    }
  }
  for (const auto& [key, s] : faces)
    if ((s.outer && s.uses != 1) || (!s.outer && s.uses != 2)) return false;

  // Commit.
  std::unordered_set<std::uint32_t> oldVertices;
  for (const TetId t : oldTets)
    for (int m = 0; m < 4; ++m) oldVertices.insert(mesh.vertex(t, m).index);
  mesh.setCertifiedDelaunay(false);
  for (const TetId t : oldTets) mesh.freeTet(t);
  std::vector<TetId> ids(newTets.size());
  for (std::size_t k = 0; k < newTets.size(); ++k)
    ids[k] = mesh.createTet(newTets[k][0], newTets[k][1], newTets[k][2], newTets[k][3]);
  for (const auto& [key, s] : faces) {
    const TetId t = ids[s.first / 4];
    const int j = static_cast<int>(s.first % 4);
    if (s.outer) {
      mesh.setAdjacentCode(t, j, s.outerCode);
      if (s.outerCode != kNone) mesh.setAdjacentCode(del3d::codeTet(s.outerCode), del3d::codeFace(s.outerCode), del3d::faceCode(t, j));
      mesh.setConstrainedBit(t, j, s.constrained);
    } else {
      const TetId u = ids[s.second / 4];
      mesh.link(t, j, u, static_cast<int>(s.second % 4));
    }
  }
  for (std::size_t k = 0; k < newTets.size(); ++k)
    for (int m = 0; m < 4; ++m) {
      mesh.setVertexTet(newTets[k][m], ids[k]);
      oldVertices.erase(newTets[k][m].index);
    }
  for (const std::uint32_t v : oldVertices) mesh.setVertexTet(VertexId(v), TetId());
  if (out) *out = std::move(ids);
  return true;
}

}  // namespace aniso::volume
