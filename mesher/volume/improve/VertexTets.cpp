#include "mesher/volume/improve/VertexTets.h"

namespace aniso::improve3d {

VertexTets::VertexTets(const del3d::TetMesh& mesh) : first_(mesh.numVertices() + 1, 0) {
  const std::size_t nv = mesh.numVertices();
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k)
    if (mesh.isAlive(del3d::TetId(k)))
      for (int i = 0; i < 4; ++i) ++first_[mesh.tetVertices(del3d::TetId(k))[i] + 1];
  for (std::size_t v = 0; v < nv; ++v) first_[v + 1] += first_[v];
  tets_.resize(first_[nv]);
  std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k)
    if (mesh.isAlive(del3d::TetId(k)))
      for (int i = 0; i < 4; ++i) tets_[fill[mesh.tetVertices(del3d::TetId(k))[i]]++] = k;
}

}  // namespace aniso::improve3d
