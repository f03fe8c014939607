#include "mesher/volume/improve/TetScores.h"

namespace aniso::improve3d {

TetScores::TetScores(const del3d::TetMesh& mesh, const VertexMetrics& vm)
    : mesh_(mesh), vm_(vm), score_(mesh.tetSlots(), 0.0) {
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k)
    if (mesh.isAlive(del3d::TetId(k))) score_[k] = vm.score(del3d::TetId(k));
}

bool TetScores::valid() const {
  for (std::uint32_t k = 0; k < mesh_.tetSlots(); ++k) {
    const del3d::TetId t(k);
    if (mesh_.isAlive(t) && (k >= score_.size() || score_[k] != vm_.score(t))) return false;
  }
  return true;
}

}  // namespace aniso::improve3d
