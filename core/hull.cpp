#include "core/hull.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>

namespace mc {

Hull convex_hull(const std::vector<Vec3>& points) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<K::Point_3>;
  Hull h;
  if (points.size() < 4) return h;
  std::vector<K::Point_3> pts;
  pts.reserve(points.size());
  for (const Vec3& p : points) pts.emplace_back(p.x, p.y, p.z);
  Mesh m;
  CGAL::convex_hull_3(pts.begin(), pts.end(), m);
  if (m.number_of_faces() < 4) return h;  // coplanar input: no volume
  // CGAL returns the facets in an order that depends on memory addresses, so everything below is
  // made independent of it (byte-identical results whatever the thread count): the interior
  // point is the mean of the input points, each facet starts at its lexicographically smallest
  // vertex, and volumes are summed in sorted order.
  Vec3 o;
  for (const Vec3& p : points) o += p;
  o = o / static_cast<double>(points.size());
  auto less = [](const Vec3& a, const Vec3& b) {
    return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
  };
  std::vector<double> parts;
  std::vector<std::pair<std::vector<Vec3>, Plane>> facets;
  for (auto f : m.faces()) {
    std::vector<Vec3> poly;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      const auto& p = m.point(v);
      poly.push_back({p.x(), p.y(), p.z()});
    }
    if (poly.size() < 3) continue;
    std::rotate(poly.begin(), std::min_element(poly.begin(), poly.end(), less), poly.end());
    Vec3 area;
    for (size_t i = 1; i + 1 < poly.size(); ++i) area += cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
    const double len = norm(area);
    if (len <= 0) continue;
    Vec3 n = area / len;
    if (dot(n, poly[0] - o) < 0) n = -n;
    parts.push_back(std::abs(dot(poly[0] - o, area)) / 6.0);
    // A sliver facet's double normal can be tilted: push its plane out to the farthest point so
    // that every facet is a true supporting plane (the half-space still contains the hull).
    double far = -1e300;
    for (const Vec3& q : points) far = std::max(far, dot(n, q));
    facets.push_back({std::move(poly), Plane{n, -far}});
  }
  std::sort(parts.begin(), parts.end());
  for (double v : parts) h.volume += v;
  std::sort(facets.begin(), facets.end(), [&](const auto& a, const auto& b) {
    return std::lexicographical_compare(a.first.begin(), a.first.end(), b.first.begin(), b.first.end(), less);
  });
  for (auto& f : facets) h.facets.push_back(f.second);
  return h;
}

}  // namespace mc
