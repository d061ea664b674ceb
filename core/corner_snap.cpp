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

size_t snap_to_lines(const std::vector<uint32_t>& planes, const std::vector<BBox>& boxes,
                     const std::vector<uint32_t>& region_plane, PlaneRegistry& registry, double tol,
                     double grow) {
  std::vector<uint32_t> regions = region_plane;
  std::sort(regions.begin(), regions.end());
  regions.erase(std::unique(regions.begin(), regions.end()), regions.end());
  size_t anchored = 0;
  for (size_t k = 0; k < planes.size(); ++k) {
    const uint32_t q = planes[k];
    if (registry.anchor(q) || registry.line_anchor(q) ||
        std::binary_search(regions.begin(), regions.end(), q))
      continue;
    const Plane Q = registry[q];
    const double on = 1e-9 * (1 + std::abs(Q.d));  // the carving's "on the plane" (carve.cpp)
    const Vec3 centre = boxes[k].center();
    double best = tol;
    uint32_t best_a = 0, best_b = 0;
    Vec3 best_u, best_p;
    for (size_t i = 0; i < regions.size(); ++i)
      for (size_t j = i + 1; j < regions.size(); ++j) {
        const Plane &A = registry[regions[i]], &B = registry[regions[j]];
        const Vec3 u = cross(A.n, B.n);
        const double uu = dot(u, u);
        if (uu < 1e-4) continue;  // (nearly) parallel planes: no well-defined line
        const Vec3 un = u / std::sqrt(uu);
        if (std::abs(dot(un, Q.n)) > 1e-6) continue;  // not parallel to Q
        // The line's point nearest the origin, then the one nearest the box's centre.
        const Vec3 p0 = (cross(B.n, u) * (-A.d) + cross(u, A.n) * (-B.d)) / uu;
        const Vec3 p = p0 + un * dot(centre - p0, un);
        BBox at;
        at.add(p);
        if (!boxes[k].overlaps(at, grow)) continue;
        const double s = std::abs(Q.signed_distance(p));
        if (s <= on || s >= best) continue;
        best = s, best_a = regions[i], best_b = regions[j], best_u = un, best_p = p;
      }
    if (!(best < tol)) continue;
    Plane line;
    line.n = normalized(Q.n - best_u * dot(best_u, Q.n));
    line.d = -dot(line.n, best_p);
    registry.set_line_anchor(q, best_a, best_b, line);
    ++anchored;
  }
  return anchored;
}

}  // namespace mc
