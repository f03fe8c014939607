// The rule deciding which overlapping part keeps a common region (cad/OverlapRule.h).
#include <gtest/gtest.h>

#include <limits>

#include "cad/OverlapRule.h"

using namespace aniso::cad;

TEST(OverlapRule, SmallerPartKeepsTheRegion) {
  const std::vector<double> vol{0, 5000, 12.5, 300};  // 1 a plate, 2 a screw, 3 a washer
  EXPECT_EQ(regionOwner({1, 2}, vol), 2);
  EXPECT_EQ(regionOwner({1, 3}, vol), 3);
  EXPECT_EQ(regionOwner({1, 2, 3}, vol), 2);
  EXPECT_EQ(regionOwner({3, 1}, vol), 3);
}

TEST(OverlapRule, TiesGoToThePartFirstInTheFile) {
  const std::vector<double> vol{0, 1000, 1000 * (1 + 0.1 * kVolumeTieRel), 1000 * (1 - 0.1 * kVolumeTieRel)};
  EXPECT_EQ(regionOwner({1, 2}, vol), 1);
  EXPECT_EQ(regionOwner({2, 1}, vol), 1);
  EXPECT_EQ(regionOwner({3, 2}, vol), 2);
  // Beyond the tie tolerance the volume decides again.
  const std::vector<double> apart{0, 1000, 1000 * (1 - 10 * kVolumeTieRel)};
  EXPECT_EQ(regionOwner({1, 2}, apart), 2);
}

TEST(OverlapRule, PairsSumTheirRegionsAndNameTheKeeper) {
  // Region 1: parts 1, 2 (kept by 2); region 2: parts 1, 2, 3 (kept by 3); region 3: 1, 2 (kept by 1).
  const std::vector<CommonRegion> regions{{{1, 2}, 4.0, 2, {}, 0}, {{1, 2, 3}, 1.0, 3, {}, 0}, {{1, 2}, 2.0, 1, {}, 0}};
  const std::vector<Overlap> pairs = overlapPairs(regions);
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(std::make_pair(pairs[0].a, pairs[0].b), std::make_pair(1, 2));
  EXPECT_DOUBLE_EQ(pairs[0].volume, 7.0);
  EXPECT_EQ(pairs[0].assignedTo, 2);  // 4 kept by 2 against 2 kept by 1
  EXPECT_EQ(std::make_pair(pairs[1].a, pairs[1].b), std::make_pair(1, 3));
  EXPECT_DOUBLE_EQ(pairs[1].volume, 1.0);
  EXPECT_EQ(pairs[1].assignedTo, 3);
  EXPECT_EQ(std::make_pair(pairs[2].a, pairs[2].b), std::make_pair(2, 3));
  EXPECT_EQ(pairs[2].assignedTo, 3);
  // The volume counted twice or more: 4 + 2 × 1 + 2.
  EXPECT_DOUBLE_EQ(overlapExcess(regions), 8.0);
}

TEST(OverlapRule, UnassignedRegionsNameNoKeeper) {
  const std::vector<Overlap> pairs = overlapPairs({{{1, 2}, 3.0, 0, {}, 0}});
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].assignedTo, 0);
}

namespace {
/// A region of parts 1 (5000) and 2 (3) measured as a film or not.
CommonRegion region(double volume, double area, double width1, double width2) {
  CommonRegion r;
  r.parts = {1, 2};
  r.volume = volume;
  r.area = area;
  r.width = {width1, width2};
  return r;
}
}  // namespace

TEST(OverlapRule, AFilmGoesWhereItLeavesNoNarrowFaces) {
  const std::vector<double> vol{0, 5000, 3};  // 1 a body, 2 a pin standing 2 µm deep on it
  const double diag = 300;
  // Film 0.002 thick (2 × 0.002 / 2 = 0.002 < 1e-4 × 300): kept in the pin, the body would get
  // the pin's 0.002-wide side strips; kept in the body, the pin gets a 0.5-wide face.
  EXPECT_EQ(regionOwner(region(0.002, 2.0, 0.5, 0.002), vol, diag), 1);
  // Same widths, but a region 0.25 thick is no film: the smaller part keeps it.
  EXPECT_EQ(regionOwner(region(0.5, 4.0, 0.5, 0.002), vol, diag), 2);
  // A film whose choices differ by less than 1 / kFilmWidthRatio: the volume rule.
  EXPECT_EQ(regionOwner(region(0.002, 2.0, 0.5, 0.5 * kFilmWidthRatio * 1.01), vol, diag), 2);
  EXPECT_EQ(regionOwner(region(0.002, 2.0, 0.5, 0.5 * kFilmWidthRatio * 0.99), vol, diag), 1);
  // Unmeasured widths or area: the volume rule.
  CommonRegion unmeasured = region(0.002, 2.0, 0.5, 0.002);
  unmeasured.width.clear();
  EXPECT_EQ(regionOwner(unmeasured, vol, diag), 2);
  unmeasured = region(0.002, 0.0, 0.5, 0.002);
  EXPECT_EQ(regionOwner(unmeasured, vol, diag), 2);
  // A part that adds no face at all (infinite width) is the widest choice.
  EXPECT_EQ(regionOwner(region(0.002, 2.0, std::numeric_limits<double>::infinity(), 0.002), vol, diag), 1);
}

TEST(OverlapRule, PreparedVolumeCountsEachMergedRegionOnce) {
  Overlap kept;
  kept.a = 1;
  kept.b = 2;
  kept.volume = 5;
  kept.assignedTo = 2;
  Overlap left = kept;  // --overlaps keep: both parts keep it, nothing to subtract
  left.assignedTo = 0;
  EXPECT_DOUBLE_EQ(preparedVolumeError(100, 95, {kept}), 0.0);
  EXPECT_DOUBLE_EQ(preparedVolumeError(100, 100, {left}), 0.0);
  EXPECT_DOUBLE_EQ(preparedVolumeError(100, 100, {kept}), 0.05);  // the overlap still counted twice
  EXPECT_DOUBLE_EQ(preparedVolumeError(1910.5, 9.5, {}), (9.5 - 1910.5) / 1910.5);  // a body lost to a repair
  EXPECT_DOUBLE_EQ(preparedVolumeError(0, 3, {}), 0.0);
}
