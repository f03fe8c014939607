#include "mesher/volume/SplitRounds.h"

namespace aniso {

bool SplitRounds::stop(int round, std::size_t missing) {
  if (round == 0) {
    first_ = best_ = missing;
  } else if (missing < best_) {
    best_ = missing;
    stalled_ = 0;
  } else {
    ++stalled_;
  }
  return missing == 0 || round >= maxRounds_ || missing > 2 * first_ || (maxStalled_ > 0 && stalled_ >= maxStalled_);
}

}  // namespace aniso
