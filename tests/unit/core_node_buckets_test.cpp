// bucketByNode (mesher/core/NodeBuckets.h): the same order as a stable sort by node, empty
// buckets included.
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "mesher/core/NodeBuckets.h"

TEST(CoreNodeBuckets, StableSortByNodeInLinearTime) {
  std::vector<std::pair<int, int>> items;  // (node, position in the input)
  std::uint64_t x = 7;
  for (int i = 0; i < 2000; ++i) {
    x = x * 6364136223846793005ull + 1442695040888963407ull;
    items.push_back({static_cast<int>((x >> 33) % 97), i});
  }
  const std::size_t nodes = 100;  // nodes 97..99 have no item
  aniso::NodeBuckets<std::pair<int, int>> b =
      aniso::bucketByNode(std::span<const std::pair<int, int>>(items), nodes, [](const auto& p) { return p.first; });
  ASSERT_EQ(b.nodes(), nodes);
  std::vector<std::pair<int, int>> ref = items;
  std::stable_sort(ref.begin(), ref.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
  EXPECT_EQ(b.items, ref);
  for (std::size_t a = 0; a < nodes; ++a)
    for (const auto& p : b.bucket(a)) EXPECT_EQ(p.first, static_cast<int>(a));
  EXPECT_TRUE(b.bucket(98).empty());
  EXPECT_EQ(b.start.back(), items.size());
}

TEST(CoreNodeBuckets, NoItems) {
  const std::vector<int> none;
  aniso::NodeBuckets<int> b = aniso::bucketByNode(std::span<const int>(none), 3, [](int v) { return v; });
  EXPECT_EQ(b.nodes(), 3u);
  for (std::size_t a = 0; a < 3; ++a) EXPECT_TRUE(b.bucket(a).empty());
}
