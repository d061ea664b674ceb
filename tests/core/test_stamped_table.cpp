// The per-thread tables by id whose rounds start without clearing (core/stamped_table.hpp).
#include <gtest/gtest.h>

#include "core/stamped_table.hpp"

namespace mc {
namespace {

TEST(StampedTable, EntriesLastOneRound) {
  StampedTable<int> t;
  t.next_round(4);
  EXPECT_EQ(t.find(2), nullptr);
  t.set(2, 7);
  ASSERT_NE(t.find(2), nullptr);
  EXPECT_EQ(*t.find(2), 7);
  *t.find(2) = 8;
  EXPECT_EQ(*t.find(2), 8);
  t.next_round(4);  // a new round: what the last one set is stale
  EXPECT_EQ(t.find(2), nullptr);
  t.next_round(10);  // grown: the new ids are stale too
  EXPECT_EQ(t.find(9), nullptr);
  EXPECT_EQ(t.set(9, 3), 3);
  EXPECT_EQ(t.find(2), nullptr);
}

// 2^32 rounds wrap the stamp: an entry set 2^32 rounds ago must not come back.
TEST(StampedTable, AWrappedStampClearsTheTable) {
  StampedTable<int> t;
  t.next_round(2);
  t.set(0, 1);
  for (uint64_t r = 0; r < (uint64_t(1) << 32) - 1; ++r) t.next_round(2);
  EXPECT_EQ(t.find(0), nullptr);
}

}  // namespace
}  // namespace mc
