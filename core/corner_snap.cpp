#include "core/corner_snap.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <tuple>

namespace mc {

namespace {

// The common point of three planes; false when they are nearly dependent (|det| < min_det).
bool meet(const Plane& a, const Plane& b, const Plane& c, double min_det, Vec3& x) {
  const Vec3 bc = cross(b.n, c.n), ca = cross(c.n, a.n), ab = cross(a.n, b.n);
  const double det = dot(a.n, bc);
  if (!(std::abs(det) >= min_det)) return false;
  x = (bc * a.d + ca * b.d + ab * c.d) * (-1.0 / det);
  return true;
}

using Key = std::tuple<double, double, double>;

}  // namespace

size_t snap_corners(const PolygonMesh& mesh, const std::vector<PlaneRegion>& regions,
                    const std::vector<uint32_t>& region_plane, PlaneRegistry& registry, double tol) {
  // Corner position -> the planes of the faces around it (with the largest region area each).
  std::map<Key, std::map<uint32_t, double>> corners;
  for (size_t r = 0; r < regions.size(); ++r)
    for (uint32_t f : regions[r].faces)
      for (const auto& ring : mesh.faces[f].rings)
        for (uint32_t v : ring) {
          if (v >= mesh.vertices.size()) continue;
          const Vec3& p = mesh.vertices[v];
          double& area = corners[Key{p.x, p.y, p.z}][region_plane[r]];
          area = std::max(area, regions[r].area);
        }

  // Planes an anchored plane depends on (transitively), to refuse cycles.
  std::function<bool(uint32_t, uint32_t)> depends_on = [&](uint32_t id, uint32_t q) {
    if (id == q) return true;
    if (const auto* a = registry.anchor(id))
      for (uint32_t x : *a)
        if (depends_on(x, q)) return true;
    return false;
  };

  constexpr double kMinSin = 0.2;  // base planes at least ~11.5 degrees apart, well conditioned
  size_t anchored = 0;
  for (const auto& [key, around] : corners) {
    if (around.size() < 4) continue;
    const Vec3 v{std::get<0>(key), std::get<1>(key), std::get<2>(key)};
    // Largest first (they move least when snapped to), then by id.
    std::vector<std::pair<double, uint32_t>> order;
    for (const auto& [id, area] : around) order.push_back({-area, id});
    std::sort(order.begin(), order.end());
    std::vector<uint32_t> base;
    for (const auto& [neg_area, id] : order) {
      if (base.size() == 3) break;
      const Plane& p = registry[id];
      if (base.size() == 1 && norm(cross(registry[base[0]].n, p.n)) < kMinSin) continue;
      if (base.size() == 2 &&
          std::abs(dot(p.n, cross(registry[base[0]].n, registry[base[1]].n))) < kMinSin * kMinSin)
        continue;
      base.push_back(id);
    }
    if (base.size() < 3) continue;
    Vec3 x;
    if (!meet(registry[base[0]], registry[base[1]], registry[base[2]], kMinSin * kMinSin, x)) continue;
    if (norm(x - v) > 10 * tol) continue;  // the base planes meet elsewhere: not this corner
    for (const auto& [neg_area, q] : order) {
      if (std::find(base.begin(), base.end(), q) != base.end() || registry.anchor(q)) continue;
      const Plane& p = registry[q];
      const double s = p.signed_distance(x);
      if (s == 0 || std::abs(s) > tol) continue;
      bool cyclic = false;
      for (uint32_t b : base) cyclic |= depends_on(b, q);
      if (cyclic) continue;
      registry.set_anchor(q, {base[0], base[1], base[2]}, -dot(p.n, x));
      ++anchored;
    }
  }
  if (!anchored) return 0;
  // Offsets of anchored planes again, now that planes they are anchored to may have moved
  // (anchors form no cycle, see above: the recursion ends).
  std::vector<uint8_t> fresh(registry.size(), 0);
  std::function<void(uint32_t)> refresh = [&](uint32_t id) {
    const auto* a = registry.anchor(id);
    if (!a || fresh[id]) return;
    fresh[id] = 1;
    const auto via = *a;
    for (uint32_t b : via) refresh(b);
    Vec3 x;
    if (meet(registry[via[0]], registry[via[1]], registry[via[2]], 0.0, x))
      registry.set_anchor(id, via, -dot(registry[id].n, x));
  };
  for (uint32_t id = 0; id < registry.size(); ++id) refresh(id);
  return anchored;
}

}  // namespace mc
