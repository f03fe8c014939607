#include "mesher/surface/face/InnerAngleSwaps.h"

#include "mesher/delaunay/EdgeFlip.h"

namespace aniso::face {

using namespace del2d;

namespace {

class NoConflict final : public ConflictTest {
 public:
  bool inConflict(const Triangulation2d&, TriId) const override { return false; }
};

}  // namespace

const ConflictTest& innerAnglesConflict() {
  static const NoConflict test;
  return test;
}

std::size_t innerAngleSwaps(Triangulation2d& tri, std::span<const TriId> start, const PlaneTransform& m,
                            std::size_t maxFlips, std::vector<std::uint32_t>& stack, std::vector<TriId>& changed) {
  // Edges as codes 3t + i; stale codes (the triangle changed meanwhile) are simply re-read.
  stack.clear();
  for (TriId t : start)
    for (std::uint32_t i = 0; i < 3; ++i) stack.push_back(3 * t.index + i);
  std::size_t flips = 0;
  while (!stack.empty() && flips < maxFlips) {
    const std::uint32_t code = stack.back();
    stack.pop_back();
    const TriId t(code / 3);
    const int i = static_cast<int>(code % 3);
    if (!tri.isAlive(t) || tri.isConstrained(t, i) || !tri.neighbour(t, i).valid()) continue;
    if (!violatesInnerAngles(tri, t, i, m)) continue;
    const FlipPlan plan = canFlip(tri, t, i);
    if (!plan.legal) continue;
    flip(tri, plan);
    ++flips;
    changed.push_back(plan.t);
    changed.push_back(plan.u);
    // Outer edges of the new pair: t' = (a, b, d) edges 0 and 2, u' = (a, d, c) edges 0 and 1.
    stack.push_back(3 * plan.t.index + 0), stack.push_back(3 * plan.t.index + 2);
    stack.push_back(3 * plan.u.index + 0), stack.push_back(3 * plan.u.index + 1);
  }
  return flips;
}

}  // namespace aniso::face
