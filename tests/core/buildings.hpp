// Synthetic buildings built in code: extruded footprints (with optional courtyard) and a
// tower on a podium. Faces are outward-oriented unless flipped by the caller.
#pragma once
#include <utility>
#include <vector>

#include "core/polygon_mesh.hpp"

namespace mc::test {

// Prism over a CCW footprint (x, y) from z0 to z1; `hole` (CW or CCW) makes a courtyard.
inline void add_prism(PolygonMesh& m, const std::vector<std::pair<double, double>>& ring, double z0, double z1,
                      const std::vector<std::pair<double, double>>& hole = {}) {
  auto add_ring = [&](const std::vector<std::pair<double, double>>& r, double z) {
    const uint32_t base = static_cast<uint32_t>(m.vertices.size());
    for (auto [x, y] : r) m.vertices.push_back({x, y, z});
    return base;
  };
  const int roof = m.label_index("RoofSurface"), wall = m.label_index("WallSurface"), ground = m.label_index("GroundSurface");
  const uint32_t b = add_ring(ring, z0), t = add_ring(ring, z1);
  const uint32_t n = static_cast<uint32_t>(ring.size());
  Polygon floor, top;
  for (uint32_t i = 0; i < n; ++i) {
    floor.rings.resize(1);
    top.rings.resize(1);
    floor.rings[0].push_back(b + n - 1 - i);
    top.rings[0].push_back(t + i);
    m.faces.push_back({{{b + i, b + (i + 1) % n, t + (i + 1) % n, t + i}}, wall});
  }
  if (!hole.empty()) {
    const uint32_t hb = add_ring(hole, z0), ht = add_ring(hole, z1);
    const uint32_t k = static_cast<uint32_t>(hole.size());
    std::vector<uint32_t> fr, tr;
    for (uint32_t i = 0; i < k; ++i) {
      fr.push_back(hb + i);            // hole ring reversed relative to the outer
      tr.push_back(ht + k - 1 - i);
      // Courtyard walls face into the courtyard (hole given CCW).
      m.faces.push_back({{{hb + (i + 1) % k, hb + i, ht + i, ht + (i + 1) % k}}, wall});
    }
    floor.rings.push_back(fr);
    top.rings.push_back(tr);
  }
  floor.semantic = ground;
  top.semantic = roof;
  m.faces.push_back(floor);
  m.faces.push_back(top);
}

inline PolygonMesh box_building() {
  PolygonMesh m;
  add_prism(m, {{0, 0}, {10, 0}, {10, 6}, {0, 6}}, 0, 5);
  return m;
}
inline PolygonMesh l_building() {
  PolygonMesh m;
  add_prism(m, {{0, 0}, {12, 0}, {12, 5}, {5, 5}, {5, 12}, {0, 12}}, 0, 6);
  return m;
}
inline PolygonMesh u_building() {
  PolygonMesh m;
  add_prism(m, {{0, 0}, {15, 0}, {15, 12}, {10, 12}, {10, 5}, {5, 5}, {5, 12}, {0, 12}}, 0, 6);
  return m;
}
inline PolygonMesh courtyard_building() {
  PolygonMesh m;
  add_prism(m, {{0, 0}, {16, 0}, {16, 16}, {0, 16}}, 0, 6, {{5, 5}, {11, 5}, {11, 11}, {5, 11}});
  return m;
}
// A 10x10x4 podium with a 4x4x8 tower on top (a setback).
inline PolygonMesh stepped_tower() {
  PolygonMesh m;
  const int roof = m.label_index("RoofSurface"), wall = m.label_index("WallSurface"), ground = m.label_index("GroundSurface");
  auto v = [&](double x, double y, double z) {
    m.vertices.push_back({x, y, z});
    return static_cast<uint32_t>(m.vertices.size() - 1);
  };
  // Podium corners and tower corners.
  const uint32_t p0 = v(0, 0, 0), p1 = v(10, 0, 0), p2 = v(10, 10, 0), p3 = v(0, 10, 0);
  const uint32_t q0 = v(0, 0, 4), q1 = v(10, 0, 4), q2 = v(10, 10, 4), q3 = v(0, 10, 4);
  const uint32_t a0 = v(3, 3, 4), a1 = v(7, 3, 4), a2 = v(7, 7, 4), a3 = v(3, 7, 4);
  const uint32_t b0 = v(3, 3, 12), b1 = v(7, 3, 12), b2 = v(7, 7, 12), b3 = v(3, 7, 12);
  m.faces.push_back({{{p3, p2, p1, p0}}, ground});
  m.faces.push_back({{{p0, p1, q1, q0}}, wall});
  m.faces.push_back({{{p1, p2, q2, q1}}, wall});
  m.faces.push_back({{{p2, p3, q3, q2}}, wall});
  m.faces.push_back({{{p3, p0, q0, q3}}, wall});
  m.faces.push_back({{{q0, q1, q2, q3}, {a0, a3, a2, a1}}, roof});  // terrace with the tower's hole
  m.faces.push_back({{{a0, a1, b1, b0}}, wall});
  m.faces.push_back({{{a1, a2, b2, b1}}, wall});
  m.faces.push_back({{{a2, a3, b3, b2}}, wall});
  m.faces.push_back({{{a3, a0, b0, b3}}, wall});
  m.faces.push_back({{{b0, b1, b2, b3}}, roof});
  return m;
}

}  // namespace mc::test
