// KeySet (mesher/core/KeySet.h): insert reports new keys only, across growth and clear.
#include <gtest/gtest.h>

#include <set>

#include "mesher/core/KeySet.h"

using aniso::KeySet;

TEST(CoreKeySet, AgreesWithStdSetAcrossGrowthAndClear) {
  KeySet k;
  std::set<std::uint64_t> ref;
  std::uint64_t x = 12345;
  for (int round = 0; round < 2; ++round) {
    for (int i = 0; i < 5000; ++i) {
      x = x * 6364136223846793005ull + 1442695040888963407ull;
      const std::uint64_t key = (x >> 40) & 0x3FF;  // many repeats
      EXPECT_EQ(k.insert(key << 32 | (x & 3)), ref.insert(key << 32 | (x & 3)).second);
    }
    EXPECT_EQ(k.size(), ref.size());
    k.clear();
    ref.clear();
    EXPECT_EQ(k.size(), 0u);
  }
  EXPECT_TRUE(k.insert(0));
  EXPECT_FALSE(k.insert(0));
}
