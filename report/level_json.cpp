#include "report/level_json.hpp"

#include <cmath>
#include <limits>

namespace mc::report {

using ojson = nlohmann::ordered_json;

namespace {
ojson num(double v) { return std::isfinite(v) ? ojson(v) : ojson(nullptr); }
double num_of(const nlohmann::json& j, const char* key) {
  const auto& v = j.at(key);
  return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>();
}
}  // namespace

ojson level_json(const LevelOutcome& l) {
  ojson j = {{"index", l.index},
             {"threshold", l.threshold},
             {"parts", l.parts},
             {"convexity", num(l.convexity)},
             {"mean_convexity", num(l.mean_convexity)},
             {"min_convexity", num(l.min_convexity)},
             {"largest_part_share", num(l.largest_share)},
             {"cost", num(l.cost)},
             {"g", num(l.g)},
             {"h", num(l.h)},
             {"remaining_concave_edges", l.remaining_concave},
             {"nodes_expanded", l.nodes_expanded},
             {"seconds", std::round(l.seconds * 1e6) / 1e6},
             {"truncated", l.truncated},
             {"max_degree", l.max_degree},
             {"end_parts", l.end_parts}};
  if (!l.fallback.empty()) j["fallback"] = l.fallback;
  if (!l.grid_repair.empty()) j["grid_repair"] = l.grid_repair;
  return j;
}

LevelOutcome level_from_json(const nlohmann::json& j) {
  LevelOutcome l;
  l.index = j.at("index").get<size_t>();
  l.threshold = j.at("threshold").get<double>();
  l.parts = j.at("parts").get<size_t>();
  l.convexity = num_of(j, "convexity");
  l.mean_convexity = num_of(j, "mean_convexity");
  l.min_convexity = num_of(j, "min_convexity");
  l.largest_share = num_of(j, "largest_part_share");
  l.cost = num_of(j, "cost");
  l.g = num_of(j, "g");
  l.h = num_of(j, "h");
  l.remaining_concave = j.at("remaining_concave_edges").get<int>();
  l.nodes_expanded = j.at("nodes_expanded").get<int64_t>();
  l.seconds = j.at("seconds").get<double>();
  l.truncated = j.at("truncated").get<bool>();
  l.max_degree = j.at("max_degree").get<int>();
  l.end_parts = j.at("end_parts").get<int>();
  l.fallback = j.value("fallback", std::string());
  l.grid_repair = j.value("grid_repair", std::string());
  return l;
}

LevelOutcome level_outcome(const LevelResult& r, size_t index) {
  LevelOutcome l;
  l.index = index;
  l.threshold = r.lod;
  l.parts = r.parts.size();
  l.convexity = r.convexity;
  l.mean_convexity = r.mean_convexity;
  l.min_convexity = r.min_convexity;
  double total = 0, largest = 0;
  for (const auto& p : r.parts) total += p.volume, largest = std::max(largest, p.volume);
  if (total > 0) l.largest_share = largest / total;
  l.cost = r.cost, l.g = r.g, l.h = r.h;
  l.remaining_concave = r.remaining_concave;
  l.nodes_expanded = r.nodes_expanded;
  l.seconds = r.seconds;
  l.truncated = r.truncated;
  for (const auto& p : r.parts) {
    const int d = static_cast<int>(p.neighbours.size());
    l.max_degree = std::max(l.max_degree, d);
    l.end_parts += d == 1;
  }
  return l;
}

}  // namespace mc::report
