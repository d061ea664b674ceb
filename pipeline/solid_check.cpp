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
  // Vertex umbrellas: the faces around each vertex, joined through their shared edges, must form
  // one fan (two fans meeting at a vertex is not a 2-manifold either).
  std::map<std::pair<int64_t, size_t>, size_t> node;  // (vertex, face) -> union-find id
  std::vector<size_t> parent;
  std::map<std::pair<int64_t, int64_t>, size_t> edge_face;  // directed edge -> face
  auto id = [&](int64_t v, size_t f) {
    auto [it, added] = node.try_emplace({v, f}, parent.size());
    if (added) parent.push_back(it->second);
    return it->second;
  };
  auto find = [&](size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (size_t face = 0; face < shell.size(); ++face)
    for (const auto& ring : shell[face])  // every ring of a surface belongs to its face
      for (size_t i = 0; i < ring.size(); ++i) edge_face[{ring[i], ring[(i + 1) % ring.size()]}] = face;
  size_t face = 0;
  for (const auto& surface : shell) {
    for (const auto& ring : surface)
      for (size_t i = 0; i < ring.size(); ++i) {
        const int64_t a = ring[i], b = ring[(i + 1) % ring.size()];
        const size_t g = edge_face.at({b, a});
        for (int64_t v : {a, b}) parent[find(id(v, face))] = find(id(v, g));
      }
    ++face;
  }
  int64_t last = -1;
  size_t root = 0;
  bool first = true;
  for (const auto& [vf, i] : node) {
    const size_t r = find(i);
    if (first || vf.first != last) {
      first = false;
      last = vf.first;
      root = r;
    } else if (r != root) {
      return "vertex " + std::to_string(vf.first) + " joins two separate fans of faces";
    }
  }
  return {};
}

}  // namespace mc::pipeline
