// Small z-up buildings built in code for the preprocessing tests. All faces are outward-facing
// unless a helper says otherwise; every face has its own semantic label (Ground/Wall/Roof).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/polygon_mesh.hpp"
#include "core/soup.hpp"

namespace mc::test {

inline uint32_t add_vertex(PolygonMesh& m, Vec3 v) {
  m.vertices.push_back(v);
  return static_cast<uint32_t>(m.vertices.size() - 1);
}

inline void add_face(PolygonMesh& m, std::vector<uint32_t> ring, const char* label) {
  Polygon f;
  f.rings.push_back(std::move(ring));
  f.semantic = m.label_index(label);
  m.faces.push_back(std::move(f));
}

// Prism over a CCW footprint (z = 0 .. h): floor, roof and one wall per footprint edge.
inline PolygonMesh prism(const std::vector<Vec3>& footprint, double h, bool with_floor = true) {
  PolygonMesh m;
  const uint32_t n = static_cast<uint32_t>(footprint.size());
  for (const Vec3& p : footprint) add_vertex(m, {p.x, p.y, 0});
  for (const Vec3& p : footprint) add_vertex(m, {p.x, p.y, h});
  std::vector<uint32_t> floor, roof;
  for (uint32_t i = 0; i < n; ++i) {
    floor.push_back(n - 1 - i);
    roof.push_back(n + i);
    const uint32_t j = (i + 1) % n;
    add_face(m, {i, j, n + j, n + i}, "WallSurface");
  }
  if (with_floor) add_face(m, floor, "GroundSurface");
  add_face(m, roof, "RoofSurface");
  return m;
}

inline PolygonMesh box(Vec3 lo, Vec3 hi) {
  PolygonMesh m = prism({{lo.x, lo.y, 0}, {hi.x, lo.y, 0}, {hi.x, hi.y, 0}, {lo.x, hi.y, 0}}, hi.z - lo.z);
  for (Vec3& v : m.vertices) v.z += lo.z;
  return m;
}

// L-shaped footprint 10 x 8 with a 6 x 4 notch at (4..10, 4..8); 8 planes.
inline std::vector<Vec3> l_footprint() {
  return {{0, 0, 0}, {10, 0, 0}, {10, 4, 0}, {4, 4, 0}, {4, 8, 0}, {0, 8, 0}};
}
inline PolygonMesh l_prism(bool with_floor = true) { return prism(l_footprint(), 6, with_floor); }

// Gable house: footprint [0,w] x [0,l], walls up to h, ridge at height r along x (or along y
// when ridge_along_y). 7 planes: floor, 4 walls, 2 roof slopes.
inline PolygonMesh gable_house(double w = 10, double l = 8, double h = 4, double r = 7,
                               bool ridge_along_y = false, bool with_floor = true) {
  PolygonMesh m;
  if (ridge_along_y) std::swap(w, l);
  // Built with the ridge along x, then x and y are swapped (with a reflection fix) if asked.
  const uint32_t a = add_vertex(m, {0, 0, 0}), b = add_vertex(m, {w, 0, 0}), c = add_vertex(m, {w, l, 0}),
                 d = add_vertex(m, {0, l, 0});
  const uint32_t a2 = add_vertex(m, {0, 0, h}), b2 = add_vertex(m, {w, 0, h}), c2 = add_vertex(m, {w, l, h}),
                 d2 = add_vertex(m, {0, l, h});
  const uint32_t r0 = add_vertex(m, {0, l / 2, r}), r1 = add_vertex(m, {w, l / 2, r});
  if (with_floor) add_face(m, {a, d, c, b}, "GroundSurface");
  add_face(m, {a, b, b2, a2}, "WallSurface");
  add_face(m, {c, d, d2, c2}, "WallSurface");
  add_face(m, {b, c, c2, r1, b2}, "WallSurface");
  add_face(m, {d, a, a2, r0, d2}, "WallSurface");
  add_face(m, {a2, b2, r1, r0}, "RoofSurface");
  add_face(m, {c2, d2, r0, r1}, "RoofSurface");
  if (ridge_along_y) {
    for (Vec3& v : m.vertices) v = {v.y, v.x, v.z};
    for (Polygon& f : m.faces) std::reverse(f.rings[0].begin(), f.rings[0].end());  // undo the mirror
  }
  return m;
}

inline void flip_face(PolygonMesh& m, size_t f) {
  for (auto& ring : m.faces[f].rings) std::reverse(ring.begin(), ring.end());
}

inline void rotate_z(PolygonMesh& m, double deg) {
  const double c = std::cos(deg * M_PI / 180), s = std::sin(deg * M_PI / 180);
  for (Vec3& v : m.vertices) v = {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

inline void jitter(PolygonMesh& m, double amount, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (Vec3& v : m.vertices) v += Vec3{u(rng), u(rng), u(rng)};
}

// Every face gets its own copy of its vertices (what the sample OFF files look like).
inline PolygonMesh explode(const PolygonMesh& m) {
  PolygonMesh out;
  out.semantic_labels = m.semantic_labels;
  for (const Polygon& f : m.faces) {
    Polygon g = f;
    for (auto& ring : g.rings)
      for (uint32_t& v : ring) v = add_vertex(out, m.vertices[v]);
    out.faces.push_back(std::move(g));
  }
  return out;
}

// The triangles of a soup as a polygon mesh (labels carried over from the source faces).
inline PolygonMesh as_mesh(const TriangleSoup& s, const PolygonMesh& src) {
  PolygonMesh m;
  m.vertices = s.vertices;
  m.semantic_labels = src.semantic_labels;
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    Polygon f;
    f.rings.push_back({s.triangles[t][0], s.triangles[t][1], s.triangles[t][2]});
    f.semantic = src.faces[s.source_face[t]].semantic;
    m.faces.push_back(std::move(f));
  }
  return m;
}

inline double soup_area(const TriangleSoup& s) {
  double a = 0;
  for (const auto& t : s.triangles)
    a += 0.5 * norm(cross(s.vertices[t[1]] - s.vertices[t[0]], s.vertices[t[2]] - s.vertices[t[0]]));
  return a;
}

}  // namespace mc::test
