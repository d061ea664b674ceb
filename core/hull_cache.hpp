// The convex hulls of one building's decomposition, each distinct point set computed once
// (docs/algorithm.md §9.2). The search, the level passes and the levels analyse many sets of
// cells whose hull points coincide (the same part at every level, a union analysed again after a
// neighbour changed); `convex_hull` depends only on the set of its points, not their order or
// repetitions, so a hit is the hull that would be computed.
#pragma once
#include <cstdint>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "core/hull.hpp"

namespace mc {

class HullCache {
 public:
  // Thread-safe; concurrent misses on one set may both compute it (the same result).
  std::shared_ptr<const Hull> get(const std::vector<Vec3>& points);
  size_t hits() const { return hits_; }
  size_t misses() const { return misses_; }

 private:
  struct Entry {
    std::vector<Vec3> points;  // sorted, distinct
    std::shared_ptr<const Hull> hull;
  };
  // Stored points across entries at most (about 12 MB); beyond, the cache starts again empty, so
  // memory stays bounded whatever the building.
  static constexpr size_t kMaxPoints = 500000;
  std::mutex mutex_;
  std::unordered_map<uint64_t, std::vector<Entry>> entries_;  // by hash of the sorted points
  size_t stored_ = 0, hits_ = 0, misses_ = 0;
};

}  // namespace mc
