#include "core/hull.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

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
  Vec3 o{points[0]};
  for (auto f : m.faces()) {
    std::vector<Vec3> poly;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      const auto& p = m.point(v);
      poly.push_back({p.x(), p.y(), p.z()});
    }
    if (poly.size() < 3) continue;
    Vec3 area;
    for (size_t i = 1; i + 1 < poly.size(); ++i) {
      const Vec3 c = cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
      area += c;
      h.volume += dot(poly[0] - o, c) / 6.0;
    }
    const double len = norm(area);
    if (len <= 0) continue;
    const Vec3 n = area / len;
    h.facets.push_back({n, -dot(n, poly[0])});
  }
  return h;
}

}  // namespace mc
