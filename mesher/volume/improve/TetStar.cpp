#include "mesher/volume/improve/TetStar.h"

#include <algorithm>
#include <array>

namespace aniso::improve3d {
namespace {

/// Visited set of a star walk: a small open-addressing table of tet indices (stars have
/// tens of tets); beyond kTableLoad entries the walk falls back to a linear search.
constexpr std::size_t kTableSize = 256;
constexpr std::size_t kTableLoad = 160;

inline std::size_t slotOf(std::uint32_t t) { return (t * 2654435761u) >> 24; }

}  // namespace

void vertexStar(const del3d::TetMesh& mesh, del3d::VertexId v, std::vector<del3d::TetId>& star) {
  star.clear();
  const del3d::TetId first = mesh.vertexTet(v);
  if (!first.valid()) return;
  std::array<std::uint32_t, kTableSize> table;
  table.fill(del3d::kNone);
  // Returns true when t was not in the set (and adds it).
  auto insert = [&](std::uint32_t t) {
    if (star.size() >= kTableLoad) return std::find(star.begin(), star.end(), del3d::TetId(t)) == star.end();
    for (std::size_t h = slotOf(t);; h = (h + 1) & (kTableSize - 1)) {
      if (table[h] == t) return false;
      if (table[h] == del3d::kNone) {
        table[h] = t;
        return true;
      }
    }
  };
  insert(first.index);
  star.push_back(first);
  for (std::size_t k = 0; k < star.size(); ++k) {
    const del3d::TetId t = star[k];
    const std::uint32_t* tv = mesh.tetVertices(t);
    for (int i = 0; i < 4; ++i) {
      if (tv[i] == v.index) continue;  // the face opposite v does not contain it
      const del3d::TetId n = mesh.neighbour(t, i);
      if (n.valid() && insert(n.index)) star.push_back(n);
    }
  }
}

}  // namespace aniso::improve3d
