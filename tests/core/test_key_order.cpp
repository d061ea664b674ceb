// The stable order by edge-like keys without sorting every entry (core/key_order.hpp), against
// std::stable_sort: small and large groups per id, repeated keys, ids far apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "core/key_order.hpp"

namespace mc {
namespace {

std::vector<uint32_t> reference(const std::vector<uint64_t>& keys) {
  std::vector<uint32_t> order(keys.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
  return order;
}

std::vector<uint32_t> ours(const std::vector<uint64_t>& keys, size_t ids) {
  return stable_key_order(
      static_cast<uint32_t>(keys.size()), [&](uint32_t i) { return keys[i]; }, ids);
}

TEST(StableKeyOrder, IsTheStableSortOrder) {
  std::mt19937_64 rng(7);
  for (int round = 0; round < 50; ++round) {
    const uint32_t ids = 1 + static_cast<uint32_t>(rng() % 200);
    std::vector<uint64_t> keys;
    for (int i = 0; i < 500; ++i) {
      const uint64_t a = rng() % ids, b = rng() % 40;  // many repeats of each key
      keys.push_back(a << 32 | b);
    }
    EXPECT_EQ(ours(keys, ids), reference(keys)) << "round " << round;
  }
}

// One id with far more entries than the in-place sort takes (a cone's apex), in reverse order,
// each key twice: both paths give the stable order, and a later call starts clean.
TEST(StableKeyOrder, AnIdOfManyEntries) {
  std::vector<uint64_t> keys;
  for (uint32_t b = 300; b-- > 0;) {
    keys.push_back(uint64_t(5) << 32 | b);
    keys.push_back(uint64_t(2) << 32 | (b % 7));
    keys.push_back(uint64_t(5) << 32 | b);
  }
  EXPECT_EQ(ours(keys, 6), reference(keys));
  const std::vector<uint64_t> few = {uint64_t(1) << 32 | 3, uint64_t(0) << 32 | 9, uint64_t(1) << 32 | 2};
  EXPECT_EQ(ours(few, 6), (std::vector<uint32_t>{1, 2, 0}));
  EXPECT_TRUE(ours({}, 6).empty());
}

}  // namespace
}  // namespace mc
