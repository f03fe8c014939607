// crossingSegments (mesher/sizing/BoundaryGaps.h): the boundary segments of a face that cross
// another one or touch its interior, shared ends aside (exact orientation tests).
#include <gtest/gtest.h>

#include "mesher/sizing/BoundaryGaps.h"

using namespace aniso;

namespace {

BoundarySegments segments(const std::vector<std::pair<Vec2, Vec2>>& ends) {
  BoundarySegments bs;
  for (const auto& [a, b] : ends) {
    BoundarySegment s;
    s.a = a;
    s.b = b;
    s.length = (b - a).norm();
    bs.segments.push_back(s);
    bs.box.add(a);
    bs.box.add(b);
  }
  bs.loopLength = {1};
  return bs;
}

}  // namespace

TEST(BoundaryCrossing, ProperCrossingsAndTouchesAreFound) {
  const BoundarySegments bs = segments({
      {{0, 0}, {1, 1}},  // 0 crosses 1
      {{0, 1}, {1, 0}},
      {{1, 1}, {2, 1}},  // 2 shares an end with 0 only
      {{3, 0}, {3, 2}},  // 3's interior is touched by the end of 4
      {{3, 1}, {4, 1}},
      {{5, 0}, {6, 0}},  // 5 and 6 are collinear, apart
      {{6.5, 0}, {7, 0}},
  });
  EXPECT_EQ(crossingSegments(bs), (std::vector<int>{0, 1, 3, 4}));
}

TEST(BoundaryCrossing, AClosedLoopAndASlitDoNotCross) {
  // a square and a slit (one segment forward and back): shared ends only
  const BoundarySegments bs = segments({{{0, 0}, {1, 0}},
                                        {{1, 0}, {1, 1}},
                                        {{1, 1}, {0, 1}},
                                        {{0, 1}, {0, 0}},
                                        {{0.2, 0.5}, {0.6, 0.5}},
                                        {{0.6, 0.5}, {0.2, 0.5}}});
  EXPECT_TRUE(crossingSegments(bs).empty());
}

TEST(BoundaryCrossing, TwoNearArcsWhoseChordsCross) {
  // a crescent: two arcs 1e-3 apart, discretized by chords of different lengths, cross
  std::vector<std::pair<Vec2, Vec2>> ends;
  const auto arc = [&](double r, int n, double shift) {
    for (int k = 0; k < n; ++k) {
      const double t0 = 3.14159 * k / n, t1 = 3.14159 * (k + 1) / n;
      ends.push_back({{r * std::cos(t0), r * std::sin(t0) + shift}, {r * std::cos(t1), r * std::sin(t1) + shift}});
    }
  };
  arc(3.0, 16, 0);
  arc(3.0, 7, 1e-3);
  EXPECT_FALSE(crossingSegments(segments(ends)).empty());
  ends.clear();
  arc(3.0, 16, 0);
  arc(3.0, 16, 1e-3);  // the same chords, shifted: parallel, no contact
  EXPECT_TRUE(crossingSegments(segments(ends)).empty());
}
