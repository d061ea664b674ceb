#include "pipeline/solid_check.hpp"

#include <algorithm>
#include <utility>

namespace mc::pipeline {

std::string closed_shell_defect(const Shell& shell) {
  std::vector<std::pair<int64_t, int64_t>> edges;
  for (const auto& surface : shell)
    for (const auto& ring : surface) {
      if (ring.size() < 3) return "a ring has fewer than 3 vertices";
      for (size_t i = 0; i < ring.size(); ++i) {
        const int64_t a = ring[i], b = ring[(i + 1) % ring.size()];
        if (a == b) return "a ring repeats vertex " + std::to_string(a);
        edges.emplace_back(a, b);
      }
    }
  if (edges.empty()) return "the shell is empty";
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i + 1 < edges.size(); ++i)
    if (edges[i] == edges[i + 1])
      return "edge " + std::to_string(edges[i].first) + "-" + std::to_string(edges[i].second) +
             " is used twice in the same direction";
  for (const auto& [a, b] : edges)
    if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a)))
      return "edge " + std::to_string(a) + "-" + std::to_string(b) + " has no opposite (boundary edge)";
  return {};
}

}  // namespace mc::pipeline
