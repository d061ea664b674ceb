// Pipeline settings that are not algorithm parameters (those live in core/params.hpp).
#pragma once
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace mc {

struct RunConfig {
  // Which input LoD to decompose: "highest" or an explicit CityJSON lod such as "2.2".
  std::string lod = "highest";
  // Indices into Params::dec.levels of the levels written as BuildingParts, ascending and
  // unique. Empty = all levels. (YAML lists the threshold values; the loader maps them.)
  std::vector<std::size_t> output_levels;
  // Maximum buildings in flight (bounds memory). 0 = automatic: max(16, 8 × worker threads)
  // (effective_in_flight below).
  int in_flight = 0;
  // trace, debug, info, warn, error, off (spdlog's level names).
  std::string log_level = "info";
};

// The in-flight bound actually used, given the resolved worker thread count (>= 1).
inline int effective_in_flight(const RunConfig& run, int worker_threads) {
  if (run.in_flight > 0) return run.in_flight;
  // Room for the largest-first order (docs/design.md, "Largest buildings first").
  return std::max(16, 8 * (worker_threads > 0 ? worker_threads : 1));
}

// True if level index `i` is to be written (empty output_levels = all).
inline bool writes_level(const RunConfig& run, std::size_t i) {
  if (run.output_levels.empty()) return true;
  for (std::size_t l : run.output_levels)
    if (l == i) return true;
  return false;
}

}  // namespace mc
