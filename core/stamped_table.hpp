// A table by id (a complex vertex, a column) whose entries are stale until set in the current
// round: starting a round costs nothing however large the table, so one per thread serves every
// query (a part's analysis, a cell's columns) without being cleared. Its memory is the largest id
// range it has served, per thread.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mc {

template <class Entry>
class StampedTable {
 public:
  // A new round over ids below `n`: every entry is stale.
  void next_round(size_t n) {
    if (slots_.size() < n) slots_.resize(n);
    if (++stamp_ == 0) {  // wrapped: cleared once in 2^32 rounds
      for (Slot& s : slots_) s.stamp = 0;
      stamp_ = 1;
    }
  }
  // The entry of `id` set in this round, or nullptr.
  Entry* find(uint32_t id) {
    Slot& s = slots_[id];
    return s.stamp == stamp_ ? &s.entry : nullptr;
  }
  // The entry of `id`, set in this round to `value`.
  Entry& set(uint32_t id, Entry value) {
    Slot& s = slots_[id];
    s.stamp = stamp_;
    s.entry = value;
    return s.entry;
  }

 private:
  struct Slot {
    uint32_t stamp = 0;
    Entry entry{};
  };
  std::vector<Slot> slots_;
  uint32_t stamp_ = 0;
};

}  // namespace mc
