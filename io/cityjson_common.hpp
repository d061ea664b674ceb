// Small CityJSON helpers shared by the reader, the writer and the building extraction.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/vec3.hpp"

namespace mc::io {

// Versions this module reads and writes; 1.0 files have no transform and float vertices.
bool is_supported_version(const std::string& version);
// Throws ReadError naming `source` unless `version` is supported.
void check_version(const nlohmann::json& root, const std::string& source);

struct Transform {
  bool present = false;
  mc::Vec3 scale{1, 1, 1}, translate{0, 0, 0};
  mc::Vec3 apply(double x, double y, double z) const {
    return {x * scale.x + translate.x, y * scale.y + translate.y, z * scale.z + translate.z};
  }
};
// Parses root["transform"]; throws ReadError naming `source` when present but malformed.
Transform parse_transform(const nlohmann::json& root, const std::string& source);

// "EPSG:<code>" from metadata.referenceSystem (OGC URL with any EPSG version, or URN), or from the
// 1.0 metadata.crs.epsg; empty when absent or not EPSG.
std::string parse_crs(const nlohmann::json& root);

// A geometry's "lod" as text: strings as they are ("2.0" stays "2.0"), 1.0-style numbers as
// their shortest JSON form (2 -> "2", 2.2 -> "2.2"); empty when missing.
std::string lod_string(const nlohmann::json& lod);

// JSON nesting limit. CityJSON needs about ten levels; deeper input is hostile or broken, and
// nlohmann's serializer and copies recurse once per level (a 100k-deep array overflows the stack).
inline constexpr int kMaxJsonDepth = 512;
// True when `text` (one JSON value) has arrays/objects nested deeper than `limit`; a linear scan
// that skips strings, cheap enough to run before every parse.
bool nested_deeper_than(const std::string& text, int limit = kMaxJsonDepth);

// Calls f(leaf, object_id, where) for every vertex reference of the objects: the leaves of every
// geometry's "boundaries" and of every address "location". `where` is e.g. "geometry #0".
// Leaves are passed as they are, so f sees (and may fix) non-integer values; arrays nested
// deeper than any CityJSON geometry are reported through f with the array itself as the leaf.
template <class F>
void for_each_vertex_ref(nlohmann::json& objects, F&& f);

// Bounded problem list: keeps the first `cap` messages and counts the rest, so that a file with a
// million bad vertices gives a readable report.
class ProblemLog {
 public:
  explicit ProblemLog(std::vector<std::string>& out, size_t cap = 50) : out_(out), cap_(cap) {}
  ~ProblemLog() { finish(); }
  void add(std::string msg) {
    if (count_++ < cap_) out_.push_back(std::move(msg));
  }
  void finish() {
    if (count_ > cap_) out_.push_back("... and " + std::to_string(count_ - cap_) + " more problems");
    count_ = std::min(count_, cap_);
  }

 private:
  std::vector<std::string>& out_;
  size_t cap_, count_ = 0;
};

// ---- implementation of the template ----
namespace detail {
// Deepest vertex-index nesting of CityJSON: MultiSolid boundaries = solids/shells/surfaces/rings.
constexpr int kMaxBoundaryDepth = 5;
template <class F>
void walk_boundaries(nlohmann::json& node, int depth, const std::string& id, const std::string& where, F& f) {
  if (!node.is_array() || depth > kMaxBoundaryDepth) {
    f(node, id, where);
    return;
  }
  for (auto& child : node) walk_boundaries(child, depth + 1, id, where, f);
}
}  // namespace detail

template <class F>
void for_each_vertex_ref(nlohmann::json& objects, F&& f) {
  if (!objects.is_object()) return;
  for (auto it = objects.begin(); it != objects.end(); ++it) {
    nlohmann::json& obj = it.value();
    if (!obj.is_object()) continue;
    auto geoms = obj.find("geometry");
    if (geoms != obj.end() && geoms->is_array()) {
      for (size_t g = 0; g < geoms->size(); ++g) {
        auto& geom = (*geoms)[g];
        if (!geom.is_object()) continue;
        auto b = geom.find("boundaries");
        if (b == geom.end()) continue;
        const std::string where = "geometry #" + std::to_string(g);
        if (b->is_array())
          for (auto& child : *b) detail::walk_boundaries(child, 1, it.key(), where, f);
        else f(*b, it.key(), where);
      }
    }
    auto addr = obj.find("address");
    if (addr != obj.end() && addr->is_array()) {
      for (size_t a = 0; a < addr->size(); ++a) {
        auto& entry = (*addr)[a];
        if (!entry.is_object()) continue;
        auto loc = entry.find("location");
        if (loc == entry.end() || !loc->is_object()) continue;
        auto b = loc->find("boundaries");
        if (b == loc->end()) continue;
        const std::string where = "address #" + std::to_string(a);
        if (b->is_array())
          for (auto& child : *b) detail::walk_boundaries(child, 1, it.key(), where, f);
        else f(*b, it.key(), where);
      }
    }
  }
}

}  // namespace mc::io
