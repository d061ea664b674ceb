// One level's result as JSON, one schema wherever it is written: the run report's buildings, the
// per-building cache's entries, and `morphcut`'s report of one mesh (docs/output-format.md).
#pragma once
#include <nlohmann/json.hpp>

#include "core/decompose.hpp"
#include "report/outcome.hpp"

namespace mc::report {

// index, threshold, parts, convexity, mean_convexity, min_convexity, largest_part_share, cost,
// g, h, remaining_concave_edges, nodes_expanded, seconds, truncated, max_degree, end_parts, and
// fallback and grid_repair when not empty. Unknown numbers (NaN) are null; seconds to 1 µs.
nlohmann::ordered_json level_json(const LevelOutcome& l);
// The inverse (throws nlohmann::json::exception on a missing or mistyped key).
LevelOutcome level_from_json(const nlohmann::json& j);
// A searched level of core's decomposition as an outcome (the fields the search knows).
LevelOutcome level_outcome(const LevelResult& r, size_t index);

}  // namespace mc::report
