#include "core/hull_cache.hpp"

#include <algorithm>
#include <cstring>

namespace mc {

namespace {

bool less(const Vec3& a, const Vec3& b) {
  return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
}

uint64_t hash_points(const std::vector<Vec3>& pts) {
  uint64_t h = 0xcbf29ce484222325ULL;
  for (const Vec3& p : pts)
    for (double c : {p.x, p.y, p.z}) {
      uint64_t bits;
      std::memcpy(&bits, &c, sizeof bits);
      h = (h ^ bits) * 0x100000001b3ULL;
      h ^= h >> 29;
    }
  return h;
}

}  // namespace

std::shared_ptr<const Hull> HullCache::get(const std::vector<Vec3>& points) {
  std::vector<Vec3> key = points;
  std::sort(key.begin(), key.end(), less);
  key.erase(std::unique(key.begin(), key.end(),
                        [](const Vec3& a, const Vec3& b) { return !less(a, b) && !less(b, a); }),
            key.end());
  const uint64_t h = hash_points(key);
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (auto it = entries_.find(h); it != entries_.end())
      for (const Entry& e : it->second)
        if (e.points == key) {
          ++hits_;
          return e.hull;
        }
    ++misses_;
  }
  auto hull = std::make_shared<const Hull>(convex_hull(key));
  const std::lock_guard<std::mutex> lock(mutex_);
  if (stored_ + key.size() > kMaxPoints) {
    entries_.clear();
    stored_ = 0;
  }
  stored_ += key.size();
  entries_[h].push_back({std::move(key), hull});
  return hull;
}

}  // namespace mc
