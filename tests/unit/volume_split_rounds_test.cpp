// SplitRounds (mesher/volume/SplitRounds.h): when the volume mesher stops splitting the
// boundary entities recovery left missing, on the sequences real models gave.
#include <gtest/gtest.h>

#include <vector>

#include "mesher/volume/SplitRounds.h"

using namespace aniso;

namespace {

/// The number of rounds run (stop() called) before it says stop, over `missing`.
int roundsRun(SplitRounds rounds, const std::vector<std::size_t>& missing) {
  for (std::size_t r = 0; r < missing.size(); ++r)
    if (rounds.stop(static_cast<int>(r), missing[r])) return static_cast<int>(r) + 1;
  return static_cast<int>(missing.size());
}

}  // namespace

TEST(SplitRounds, ASolidThatConvergesSlowlyRunsToTheEnd) {
  // ellipses.brep: every round leaves fewer missing
  EXPECT_EQ(roundsRun(SplitRounds(8, 2), {17, 11, 8, 6, 2, 1, 0}), 7);
}

TEST(SplitRounds, SplittingThatStallsStopsAfterTwoRoundsWithoutABetterOne) {
  // KiCad's common-mode toroid: best 298 at round 2, then 298 and 316
  EXPECT_EQ(roundsRun(SplitRounds(8, 2), {471, 302, 298, 298, 316, 329, 327}), 5);
  // a DC-DC converter's pin: best 2 at round 1, then 5 and 2
  EXPECT_EQ(roundsRun(SplitRounds(8, 2), {3, 2, 5, 2, 7, 2, 2, 7}), 4);
  // without the stall test only the round limit stops it
  EXPECT_EQ(roundsRun(SplitRounds(8, 0), {3, 2, 5, 2, 5, 2, 2, 5, 2}), 9);
}

TEST(SplitRounds, DivergingOrDoneOrOutOfRoundsStops) {
  EXPECT_EQ(roundsRun(SplitRounds(8, 2), {10, 21}), 2);  // more than twice the first
  EXPECT_EQ(roundsRun(SplitRounds(8, 2), {4, 0}), 2);
  EXPECT_EQ(roundsRun(SplitRounds(2, 0), {9, 8, 7, 6}), 3);  // rounds 0, 1, 2
}
