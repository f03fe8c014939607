#pragma once
// When the volume mesher stops splitting unrecovered boundary entities (VolumeMesher.h,
// maxSplitRounds): no entity missing; the round limit reached; twice as many missing as at
// first (splitting diverges); or `maxStalled` rounds in a row that leave no fewer missing
// than the best round so far (splitting stalls: 0 turns this test off).
#include <cstddef>

namespace aniso {

class SplitRounds {
 public:
  SplitRounds(int maxRounds, int maxStalled) : maxRounds_(maxRounds), maxStalled_(maxStalled) {}

  /// Called once per round, in order from round 0, with the entities missing after it:
  /// true when no further round is to run.
  bool stop(int round, std::size_t missing);

 private:
  int maxRounds_, maxStalled_;
  std::size_t first_ = 0, best_ = 0;
  int stalled_ = 0;
};

}  // namespace aniso
