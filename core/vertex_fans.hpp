// Vertex umbrellas of a polygon surface: at a vertex, each face corner (prev, v, next) joins the
// vertex's two neighbours along that face; a 2-manifold surface links all of a vertex's neighbours
// into one fan. Two fans at one vertex (two solids touching at a corner, a ring touching itself)
// are val3dity's 303. Used by the solid checks on triangles and on rings.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "core/union_find.hpp"

namespace mc {

// `corners`: every face corner as {prev, v, next}. Returns the vertices around which the corners
// form more than one fan, with the number of fans, ascending by vertex.
template <class Id>
std::vector<std::pair<Id, size_t>> split_fans(std::vector<std::array<Id, 3>> corners) {
  std::sort(corners.begin(), corners.end(), [](const auto& a, const auto& b) { return a[1] < b[1]; });
  std::vector<std::pair<Id, size_t>> out;
  std::vector<Id> around;
  for (size_t i = 0; i < corners.size();) {
    size_t j = i;
    around.clear();
    for (; j < corners.size() && corners[j][1] == corners[i][1]; ++j) {
      around.push_back(corners[j][0]);
      around.push_back(corners[j][2]);
    }
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    auto index = [&](Id n) {
      return static_cast<uint32_t>(std::lower_bound(around.begin(), around.end(), n) - around.begin());
    };
    UnionFind fans(around.size());
    for (size_t k = i; k < j; ++k) fans.link(index(corners[k][0]), index(corners[k][2]));
    size_t roots = 0;
    for (uint32_t k = 0; k < around.size(); ++k) roots += fans.find(k) == k;
    if (roots > 1) out.emplace_back(corners[i][1], roots);
    i = j;
  }
  return out;
}

}  // namespace mc
