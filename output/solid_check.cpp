#include "output/solid_check.hpp"

#include <algorithm>
#include <map>
#include <utility>

#include "core/union_find.hpp"
#include "core/vertex_fans.hpp"

namespace mc::output {

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
  // Vertex umbrellas: the face corners (prev, v, next) at each vertex must link its edges into
  // one cycle (two fans meeting at a vertex, or a ring touching itself, are not 2-manifold).
  std::vector<std::array<int64_t, 3>> corners;
  for (const auto& surface : shell)
    for (const auto& ring : surface)
      for (size_t i = 0; i < ring.size(); ++i)
        corners.push_back({ring[(i + ring.size() - 1) % ring.size()], ring[i], ring[(i + 1) % ring.size()]});
  if (const auto split = split_fans(std::move(corners)); !split.empty())
    return "vertex " + std::to_string(split.front().first) + " joins two separate fans of faces";
  // One shell: every face reachable from every other through shared edges.
  std::map<std::pair<int64_t, int64_t>, size_t> edge_face;  // directed edge -> surface
  for (size_t f = 0; f < shell.size(); ++f)
    for (const auto& ring : shell[f])
      for (size_t i = 0; i < ring.size(); ++i) edge_face[{ring[i], ring[(i + 1) % ring.size()]}] = f;
  mc::UnionFind faces(shell.size());
  for (const auto& [e, f] : edge_face)
    faces.link(static_cast<uint32_t>(f), static_cast<uint32_t>(edge_face.at({e.second, e.first})));
  for (uint32_t f = 1; f < shell.size(); ++f)
    if (faces.find(f) != faces.find(0)) return "the faces form more than one connected shell";
  return {};
}

}  // namespace mc::output
