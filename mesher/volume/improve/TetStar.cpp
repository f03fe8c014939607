#include "mesher/volume/improve/TetStar.h"

#include <algorithm>

namespace aniso::improve3d {

void vertexStar(const del3d::TetMesh& mesh, del3d::VertexId v, std::vector<del3d::TetId>& star) {
  star.clear();
  const del3d::TetId first = mesh.vertexTet(v);
  if (!first.valid()) return;
  star.push_back(first);
  for (std::size_t k = 0; k < star.size(); ++k) {
    const del3d::TetId t = star[k];
    const int iv = mesh.localIndex(t, v);
    for (int i = 0; i < 4; ++i) {
      if (i == iv) continue;  // the face opposite v does not contain it
      const del3d::TetId n = mesh.neighbour(t, i);
      if (n.valid() && std::find(star.begin(), star.end(), n) == star.end()) star.push_back(n);
    }
  }
}

}  // namespace aniso::improve3d
