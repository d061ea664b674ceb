// Disjoint sets over 0..n-1 (path halving), for the many "which of these are connected" questions
// of the geometry: welded vertices, coplanar hull facets, closed shells, concave-line chains, groups
// of parts, components of a part graph.
#pragma once
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace mc {

class UnionFind {
 public:
  explicit UnionFind(size_t n = 0) : parent_(n) { std::iota(parent_.begin(), parent_.end(), uint32_t{0}); }
  size_t size() const { return parent_.size(); }
  // n singletons again, reusing the storage (for many small questions in a row).
  void reset(size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), uint32_t{0});
  }
  bool is_root(uint32_t x) const { return parent_[x] == x; }
  uint32_t find(uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // a's set joins b's: b's root becomes the root of both.
  void link(uint32_t a, uint32_t b) { parent_[find(a)] = find(b); }
  // The smaller root stays the root (a set's root is then its smallest member).
  void unite_low(uint32_t a, uint32_t b) {
    a = find(a);
    b = find(b);
    if (a < b) parent_[b] = a;
    else parent_[a] = b;
  }

 private:
  std::vector<uint32_t> parent_;
};

}  // namespace mc
