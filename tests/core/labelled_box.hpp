// An axis-aligned box [o, o + d] with outward faces, labelled like a building (ground, roof,
// three walls and a closure surface): for the measures, encoding and solid-check tests.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "core/polygon_mesh.hpp"

namespace mc::test {

inline PolygonMesh labelled_box(Vec3 o, Vec3 d) {
  PolygonMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({o.x + (i & 1) * d.x, o.y + ((i >> 1) & 1) * d.y, o.z + ((i >> 2) & 1) * d.z});
  auto face = [&](std::vector<uint32_t> r, const char* l) {
    Polygon p;
    p.rings.push_back(std::move(r));
    p.semantic = m.label_index(l);
    m.faces.push_back(std::move(p));
  };
  face({0, 2, 3, 1}, "GroundSurface");
  face({4, 5, 7, 6}, "RoofSurface");
  face({0, 1, 5, 4}, "WallSurface");
  face({2, 6, 7, 3}, "WallSurface");
  face({0, 4, 6, 2}, "WallSurface");
  face({1, 3, 7, 5}, "ClosureSurface");
  return m;
}

}  // namespace mc::test
