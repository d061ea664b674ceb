// Best-first branch and bound over cutting planes (docs/algorithm.md §12).
//
// Nodes are sets of parts (ids into a per-search arena of analysed parts, deduplicated by
// cell bitset); splits are memoised per (part, plane). The cost f = g + σ·h is a sum over
// parts, so each child's cost is known from per-part values before the child is built, and
// only the best `max_children` combinations of an expansion are enumerated (lazily, in cost
// order). Ties break on (cost, h, creation order), so the search is deterministic.
#pragma once
#include <cstdint>
#include <vector>

#include "core/objective.hpp"
#include "core/part.hpp"
#include "core/preprocess.hpp"

namespace mc {

struct SearchInput {
  const CellSpace* space = nullptr;
  std::vector<uint32_t> pool;  // candidate planes the space was refined by
  std::vector<Bits> positive;  // per pool plane: cells on its positive side
  AnalysisContext ctx;
  Clock::time_point deadline;
};

struct SearchResult {
  std::vector<PartAnalysis> parts;
  double cost = 0, g = 0, h = 0;
  int64_t expanded = 0;
  bool deadline_hit = false;
  bool budget_hit = false;
};

SearchResult search(const SearchInput& in, const PartAnalysis& root);

}  // namespace mc
