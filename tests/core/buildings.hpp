// Synthetic buildings built in code: extruded footprints (with optional courtyard), a tower on a
// podium, a gable house with a cross gable and one with a dormer. Faces are outward-oriented unless flipped
// by the caller.
#pragma once
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/polygon_mesh.hpp"

namespace mc::test {

// Prism over a CCW footprint (x, y) from z0 to z1; `hole` (CW or CCW) makes a courtyard.
inline void add_prism(PolygonMesh& m, const std::vector<std::pair<double, double>>& ring, double z0,
                      double z1, const std::vector<std::pair<double, double>>& hole = {}) {
  auto add_ring = [&](const std::vector<std::pair<double, double>>& r, double z) {
    const uint32_t base = static_cast<uint32_t>(m.vertices.size());
    for (auto [x, y] : r) m.vertices.push_back({x, y, z});
    return base;
  };
  const int roof = m.label_index("RoofSurface"), wall = m.label_index("WallSurface"),
            ground = m.label_index("GroundSurface");
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
      fr.push_back(hb + i);  // hole ring reversed relative to the outer
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
  const int roof = m.label_index("RoofSurface"), wall = m.label_index("WallSurface"),
            ground = m.label_index("GroundSurface");
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

inline PolygonMesh t_building() {
  PolygonMesh m;
  add_prism(m, {{0, 0}, {15, 0}, {15, 5}, {10, 5}, {10, 12}, {5, 12}, {5, 5}, {0, 5}}, 0, 6);
  return m;
}

// Builds faces from rings of points; each face is turned to face `out` (holes opposite to it),
// so the hand-written rings below need no care for their order. Shared points become one vertex.
struct FaceBuilder {
  PolygonMesh m;
  uint32_t at(const Vec3& p) {
    for (uint32_t i = 0; i < m.vertices.size(); ++i)
      if (m.vertices[i].x == p.x && m.vertices[i].y == p.y && m.vertices[i].z == p.z) return i;
    m.vertices.push_back(p);
    return static_cast<uint32_t>(m.vertices.size() - 1);
  }
  static Vec3 newell(const std::vector<Vec3>& r) {
    Vec3 n{0, 0, 0};
    for (size_t i = 0; i < r.size(); ++i) {
      const Vec3 &a = r[i], &b = r[(i + 1) % r.size()];
      n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    return n;
  }
  void face(std::vector<Vec3> outer, Vec3 out, const char* label, std::vector<Vec3> hole = {}) {
    if (dot(newell(outer), out) < 0) std::reverse(outer.begin(), outer.end());
    if (!hole.empty() && dot(newell(hole), out) > 0) std::reverse(hole.begin(), hole.end());
    Polygon f;
    f.semantic = m.label_index(label);
    f.rings.emplace_back();
    for (const Vec3& p : outer) f.rings.back().push_back(at(p));
    if (!hole.empty()) {
      f.rings.emplace_back();
      for (const Vec3& p : hole) f.rings.back().push_back(at(p));
    }
    m.faces.push_back(std::move(f));
  }
};

// Gable house 10 x 8 (eaves 4, ridge 7 along x at y = 4) with a cross gable at the back: a wing
// x 3..7, y 8..14 whose ridge (x = 5, height 6) runs along y into the main roof; its roof meets
// the back slope along two valleys, from the eave corners (3|7, 8, 4) to (5, 4 + 4/3, 6).
inline PolygonMesh cross_gable_house() {
  FaceBuilder b;
  const double yv = 4 + 4.0 / 3;  // where the wing's ridge enters the main back slope
  const Vec3 up{0, 0, 1}, down{0, 0, -1};
  b.face({{0, 0, 0}, {10, 0, 0}, {10, 8, 0}, {7, 8, 0}, {7, 14, 0}, {3, 14, 0}, {3, 8, 0}, {0, 8, 0}}, down,
         "GroundSurface");
  b.face({{0, 0, 0}, {10, 0, 0}, {10, 0, 4}, {0, 0, 4}}, {0, -1, 0}, "WallSurface");
  b.face({{0, 0, 0}, {0, 8, 0}, {0, 8, 4}, {0, 4, 7}, {0, 0, 4}}, {-1, 0, 0}, "WallSurface");
  b.face({{10, 0, 0}, {10, 8, 0}, {10, 8, 4}, {10, 4, 7}, {10, 0, 4}}, {1, 0, 0}, "WallSurface");
  b.face({{0, 8, 0}, {3, 8, 0}, {3, 8, 4}, {0, 8, 4}}, {0, 1, 0}, "WallSurface");
  b.face({{7, 8, 0}, {10, 8, 0}, {10, 8, 4}, {7, 8, 4}}, {0, 1, 0}, "WallSurface");
  b.face({{3, 8, 0}, {3, 14, 0}, {3, 14, 4}, {3, 8, 4}}, {-1, 0, 0}, "WallSurface");
  b.face({{7, 8, 0}, {7, 14, 0}, {7, 14, 4}, {7, 8, 4}}, {1, 0, 0}, "WallSurface");
  b.face({{3, 14, 0}, {7, 14, 0}, {7, 14, 4}, {5, 14, 6}, {3, 14, 4}}, {0, 1, 0}, "WallSurface");
  b.face({{0, 0, 4}, {10, 0, 4}, {10, 4, 7}, {0, 4, 7}}, {0, -3, 4}, "RoofSurface");
  b.face({{10, 8, 4}, {7, 8, 4}, {5, yv, 6}, {3, 8, 4}, {0, 8, 4}, {0, 4, 7}, {10, 4, 7}}, {0, 3, 4},
         "RoofSurface");
  b.face({{3, 14, 4}, {3, 8, 4}, {5, yv, 6}, {5, 14, 6}}, {-1, 0, 1}, "RoofSurface");
  b.face({{7, 8, 4}, {7, 14, 4}, {5, 14, 6}, {5, yv, 6}}, {1, 0, 1}, "RoofSurface");
  (void)up;
  return b.m;
}

// The same gable house (without the wing) with a flat-roofed dormer on the front slope
// (z = 4 + 0.75 y): x 4..6, front wall at y = 1, roof at 6.25, which meets the slope at y = 3.
inline PolygonMesh dormer_house() {
  FaceBuilder b;
  b.face({{0, 0, 0}, {10, 0, 0}, {10, 8, 0}, {0, 8, 0}}, {0, 0, -1}, "GroundSurface");
  b.face({{0, 0, 0}, {10, 0, 0}, {10, 0, 4}, {0, 0, 4}}, {0, -1, 0}, "WallSurface");
  b.face({{0, 8, 0}, {10, 8, 0}, {10, 8, 4}, {0, 8, 4}}, {0, 1, 0}, "WallSurface");
  b.face({{0, 0, 0}, {0, 8, 0}, {0, 8, 4}, {0, 4, 7}, {0, 0, 4}}, {-1, 0, 0}, "WallSurface");
  b.face({{10, 0, 0}, {10, 8, 0}, {10, 8, 4}, {10, 4, 7}, {10, 0, 4}}, {1, 0, 0}, "WallSurface");
  b.face({{0, 8, 4}, {10, 8, 4}, {10, 4, 7}, {0, 4, 7}}, {0, 3, 4}, "RoofSurface");
  b.face({{0, 0, 4}, {10, 0, 4}, {10, 4, 7}, {0, 4, 7}}, {0, -3, 4}, "RoofSurface",
         {{4, 1, 4.75}, {6, 1, 4.75}, {6, 3, 6.25}, {4, 3, 6.25}});
  b.face({{4, 1, 4.75}, {6, 1, 4.75}, {6, 1, 6.25}, {4, 1, 6.25}}, {0, -1, 0}, "WallSurface");
  b.face({{4, 1, 4.75}, {4, 1, 6.25}, {4, 3, 6.25}}, {-1, 0, 0}, "WallSurface");
  b.face({{6, 1, 4.75}, {6, 3, 6.25}, {6, 1, 6.25}}, {1, 0, 0}, "WallSurface");
  b.face({{4, 1, 6.25}, {6, 1, 6.25}, {6, 3, 6.25}, {4, 3, 6.25}}, {0, 0, 1}, "RoofSurface");
  return b.m;
}

}  // namespace mc::test
