#pragma once
// Geometric flipping of faces and edges by quality (thesis sec. 5.6.2): T23 for a face,
// T32 for an edge with three tets around it, T44 (both diagonals) for an edge with four.
// Legality is the kernel's (canFlip23/32/44: exact orientation, constrained faces never
// removed); a flip is applied when the worst η_M of the new tets exceeds the worst η_M of
// the old ones by more than `gain` (η_M in the mean of the vertices' tensors,
// VertexMetrics). visit() tries every flip of one tet and applies the first beneficial one;
// run() visits the tets (all, or those below a quality: a flip only helps when one of the
// tets it replaces is poor) and then the new ones until nothing changes (or a cap of
// kMaxFlipsPerTet flips per initial tet is reached). run() remembers the visits that found
// nothing: a face or an edge whose tets all existed when one of them was visited in vain was
// tried then on the same tets (the mesh changes only by run()'s flips), so it is skipped.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mesher/volume/SolidTetMesh.h"
#include "mesher/volume/improve/TetScores.h"
#include "mesher/volume/improve/VertexMetrics.h"

namespace aniso::improve3d {

/// Cap of run(): at most this many flips per tet present at its start.
inline constexpr std::size_t kMaxFlipsPerTet = 8;

struct FlipCounts {
  std::size_t f23 = 0, f32 = 0, f44 = 0;
  std::size_t total() const { return f23 + f32 + f44; }
};

class QualityFlips {
 public:
  /// With `scores` the current tets' scores are read from that cache and the created tets'
  /// are stored in it (TetScores' contract; the mesh changes only by these flips meanwhile).
  QualityFlips(SolidTetMesh& s, const VertexMetrics& vm, double gain, TetScores* scores = nullptr)
      : s_(s), vm_(vm), gain_(gain), scores_(scores) {}

  /// Tries the flips of the live tet t; on success appends the new tets to `created` and
  /// returns true (t is then dead).
  bool visit(del3d::TetId t, std::vector<del3d::TetId>& created);
  /// The live tets with η_M < candidateBelow (> 1: all), then the created ones, until
  /// stable.
  void run(double candidateBelow);
  const FlipCounts& counts() const { return counts_; }

 private:
  bool tryFace(del3d::TetId t, int i, std::vector<del3d::TetId>& created);
  bool tryEdge(del3d::TetId t, int i, int j, std::vector<del3d::TetId>& created);
  double score(del3d::TetId t) const { return scores_ ? (*scores_)[t] : vm_.score(t); }
  /// The flip epoch: 1 + the number of flips made.
  std::uint32_t epoch() const { return static_cast<std::uint32_t>(counts_.total() + 1); }
  /// run()'s memo: true when one of `tets` was visited in vain while all of them existed.
  bool triedBefore(std::span<const del3d::TetId> tets) const;
  template <class Range>
  double worst(const Range& tets) const;
  template <std::size_t N>
  void created(const std::array<del3d::TetId, N>& tets, std::vector<del3d::TetId>& out);

  SolidTetMesh& s_;
  const VertexMetrics& vm_;
  double gain_;
  TetScores* scores_;
  FlipCounts counts_;
  /// Per slot, during run() only: the epoch at which the visit of its tet found nothing (0:
  /// none) and the epoch at which its tet was made (0: before run()).
  std::vector<std::uint32_t> failedAt_, createdAt_;
};

}  // namespace aniso::improve3d
