#include "pipeline/solid_check.hpp"

#include <algorithm>
#include <map>
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
  // Vertex umbrellas: the face corners (prev, v, next) at each vertex must link its edges into
  // one cycle (two fans meeting at a vertex, or a ring touching itself, are not 2-manifold).
  std::map<int64_t, std::map<int64_t, int64_t>> fan;  // vertex -> neighbour -> union-find parent
  auto find = [](std::map<int64_t, int64_t>& uf, int64_t x) {
    while (uf[x] != x) x = uf[x] = uf[uf[x]];
    return x;
  };
  for (const auto& surface : shell)
    for (const auto& ring : surface)
      for (size_t i = 0; i < ring.size(); ++i) {
        const int64_t v = ring[i], prev = ring[(i + ring.size() - 1) % ring.size()], next = ring[(i + 1) % ring.size()];
        auto& uf = fan[v];
        uf.try_emplace(prev, prev);
        uf.try_emplace(next, next);
        uf[find(uf, prev)] = find(uf, next);
      }
  for (auto& [v, uf] : fan) {
    const int64_t first = find(uf, uf.begin()->first);
    for (auto& [n, p] : uf)
      if (find(uf, n) != first) return "vertex " + std::to_string(v) + " joins two separate fans of faces";
  }
  // One shell: every face reachable from every other through shared edges.
  std::map<std::pair<int64_t, int64_t>, size_t> edge_face;  // directed edge -> surface
  for (size_t f = 0; f < shell.size(); ++f)
    for (const auto& ring : shell[f])
      for (size_t i = 0; i < ring.size(); ++i) edge_face[{ring[i], ring[(i + 1) % ring.size()]}] = f;
  std::vector<size_t> parent(shell.size());
  for (size_t f = 0; f < parent.size(); ++f) parent[f] = f;
  auto root = [&](size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const auto& [e, f] : edge_face) parent[root(f)] = root(edge_face.at({e.second, e.first}));
  for (size_t f = 1; f < shell.size(); ++f)
    if (root(f) != root(0)) return "the faces form more than one connected shell";
  return {};
}

}  // namespace mc::pipeline
