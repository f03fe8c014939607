// chainLoopUses (mesher/model/ChainLoop.h): a loop's uses put in walking order.
#include <gtest/gtest.h>

#include <memory>
#include <numbers>

#include "mesher/geometry/Line2d.h"
#include "mesher/model/ChainLoop.h"

namespace aniso {
namespace {

constexpr double kPi = std::numbers::pi;

/// An edge from vertex a to vertex b with one straight pcurve on face 0, from p to q.
ModelEdge edge(int a, int b, const Vec2& p, const Vec2& q) {
  ModelEdge e;
  e.v0 = a;
  e.v1 = b;
  e.t1 = 1;
  e.faces = {0};
  e.pcurves.push_back({0, std::make_shared<Line2d>(p, q), 0.0, 1.0, false});
  return e;
}

/// The half torus of KiCad's beaded test points in (u, v) = [π, 2π] × [0, 2π]: edge 0 runs
/// A → B along v = 0, edge 1 is the profile circle at u = 2π (closed at A), edge 2 runs
/// B → A along v = 2π, edge 3 the profile circle at u = π (closed at B).
Model halfTorus() {
  Model m;
  m.vertices.resize(2);
  m.edges.push_back(edge(0, 1, Vec2(2 * kPi, 0), Vec2(kPi, 0)));
  m.edges.push_back(edge(0, 0, Vec2(2 * kPi, 2 * kPi), Vec2(2 * kPi, 0)));
  m.edges.push_back(edge(1, 0, Vec2(kPi, 2 * kPi), Vec2(2 * kPi, 2 * kPi)));
  m.edges.push_back(edge(1, 1, Vec2(kPi, 0), Vec2(kPi, 2 * kPi)));
  return m;
}

std::vector<int> order(const std::vector<EdgeUse>& uses) {
  std::vector<int> out;
  for (const EdgeUse& u : uses) out.push_back(u.edge);
  return out;
}

TEST(ChainLoop, StoredOutOfOrderIsWalkedByVertexAndNearestUv) {
  const Model m = halfTorus();
  std::vector<EdgeUse> uses{{0, false, 0}, {1, false, 0}, {2, false, 0}, {3, false, 0}};
  chainLoopUses(m, uses);
  // from B two uses start: the circle at u = π where edge 0 ended, not edge 2 a period away
  EXPECT_EQ(order(uses), (std::vector<int>{0, 3, 2, 1}));
}

TEST(ChainLoop, ReversedUsesStartAtTheirSecondVertex) {
  const Model m = halfTorus();
  // walked the other way round: edge 1 reversed (A, from v = 0 up), edge 2 reversed (A → B), ...
  std::vector<EdgeUse> uses{{1, true, 0}, {3, true, 0}, {2, true, 0}, {0, true, 0}};
  chainLoopUses(m, uses);
  EXPECT_EQ(order(uses), (std::vector<int>{1, 2, 3, 0}));
}

TEST(ChainLoop, NoChainLeavesTheOrder) {
  Model m = halfTorus();
  m.edges[2].v0 = 0;  // edge 2 now starts at A: nothing starts at B after edge 3
  std::vector<EdgeUse> uses{{0, false, 0}, {1, false, 0}, {2, false, 0}, {3, false, 0}};
  chainLoopUses(m, uses);
  EXPECT_EQ(order(uses), (std::vector<int>{0, 1, 2, 3}));
}

}  // namespace
}  // namespace aniso
