// The order in which a stable sort by a 64-bit key would put n entries, for keys whose high 32
// bits are an id below a known bound (an edge key: its first vertex << 32 | its second): the
// entries are chained by that id in a per-thread table by id (core/stamped_table.hpp), only the
// distinct ids are sorted, and each id's few entries are put in key order in place. Linear but
// for the distinct ids' sort, where sorting every entry is not (docs/design.md, "Less work in the
// analysis, in the same order").
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/stamped_table.hpp"

namespace mc {

// The table by id that every stable_key_order on this thread uses (one per thread, not one per
// key type: each order is finished before the next one starts).
inline StampedTable<uint32_t>& key_order_table() {
  thread_local StampedTable<uint32_t> table;
  return table;
}

// Indices 0..n-1 in (key, index) order; `key(i)` is entry i's key, whose high 32 bits are below
// `ids`.
template <class KeyOf>
std::vector<uint32_t> stable_key_order(uint32_t n, KeyOf key, size_t ids) {
  constexpr uint32_t kEnd = ~0u;
  StampedTable<uint32_t>& last = key_order_table();  // id -> its latest entry
  last.next_round(ids);
  std::vector<uint32_t> before(n);  // the previous entry with the same id
  std::vector<uint32_t> firsts;
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t a = static_cast<uint32_t>(key(i) >> 32);
    if (uint32_t* l = last.find(a)) {
      before[i] = *l;
      *l = i;
    } else {
      before[i] = kEnd;
      last.set(a, i);
      firsts.push_back(a);
    }
  }
  std::sort(firsts.begin(), firsts.end());
  std::vector<uint32_t> order;
  order.reserve(n);
  auto by_key = [&](uint32_t x, uint32_t y) { return key(x) < key(y); };
  for (const uint32_t a : firsts) {
    const size_t begin = order.size();
    for (uint32_t i = *last.find(a); i != kEnd; i = before[i]) order.push_back(i);
    std::reverse(order.begin() + static_cast<long>(begin), order.end());  // indices ascending
    if (order.size() - begin > 32) {  // an id of many entries (a cone's apex): n log n, stable
      std::stable_sort(order.begin() + static_cast<long>(begin), order.end(), by_key);
      continue;
    }
    for (size_t k = begin + 1; k < order.size(); ++k) {  // insertion sort: stable, few entries
      const uint32_t x = order[k];
      size_t m = k;
      for (; m > begin && by_key(x, order[m - 1]); --m) order[m] = order[m - 1];
      order[m] = x;
    }
  }
  return order;
}

}  // namespace mc
