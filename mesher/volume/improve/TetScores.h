#pragma once
// Per-tet cache of VertexMetrics::score (the signed η_M³) for the smoothing and flipping of
// one improvement pass (sec. 5.6): every live tet is measured once when the cache is built;
// afterwards a tet's score is read, not recomputed, so a vertex star or an edge ring costs
// no mean-ratio evaluation for its current configuration. Contract: the owner keeps it
// exact — update() for every tet created (flips) and for every tet whose vertex moved or
// whose vertex's tensor changed (smoothing); the Euclidean guard of VertexMetrics must stay
// off while it is used (the cached value is the plain metric score). valid() recomputes
// every live tet and compares, for tests. Slots beyond the built size are added on update.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"
#include "mesher/volume/improve/VertexMetrics.h"

namespace aniso::improve3d {

/// The mean η_M (cube root of the score, negatives as 0) of the live tets of `mesh`, scores
/// read from `score(TetId)`: exact up to kMeanExactSlots tet slots, above estimated from
/// every kMeanStride-th slot (deterministic; 1/16 of the cube roots, close to the exact mean
/// on large meshes: docs/measurements.md).
inline constexpr std::uint32_t kMeanExactSlots = 1u << 16;
inline constexpr std::uint32_t kMeanStride = 16;
template <class Score>
double sampledMeanEta(const del3d::TetMesh& mesh, const Score& score) {
  const std::uint32_t stride = mesh.tetSlots() > kMeanExactSlots ? kMeanStride : 1;
  double sum = 0;
  std::size_t n = 0;
  for (std::uint32_t k = 0; k < mesh.tetSlots(); k += stride)
    if (mesh.isAlive(del3d::TetId(k))) sum += std::cbrt(std::max(0.0, score(del3d::TetId(k)))), ++n;
  return n ? sum / static_cast<double>(n) : 0.0;
}

/// The worst-score condition of the improvement's local changes (flips, vertex removal):
/// the worst score after (η_M³) beats the worst before by `gain` in η_M (cube roots only
/// when the order alone does not decide).
inline bool beatsWorst(double after, double before, double gain) {
  return after > before && std::cbrt(after) > std::cbrt(before) + gain;
}

class TetScores {
 public:
  TetScores(const del3d::TetMesh& mesh, const VertexMetrics& vm);
  double operator[](del3d::TetId t) const { return score_[t.index]; }
  /// Recomputes t's score.
  void update(del3d::TetId t) { set(t, vm_.score(t)); }
  /// Stores a score computed elsewhere (it must equal vm.score(t)).
  void set(del3d::TetId t, double score) {
    if (t.index >= score_.size()) score_.resize(mesh_.tetSlots(), 0.0);
    score_[t.index] = score;
  }
  /// True when every live tet's cached score equals vm.score (exactly).
  bool valid() const;

 private:
  const del3d::TetMesh& mesh_;
  const VertexMetrics& vm_;
  std::vector<double> score_;
};

}  // namespace aniso::improve3d
