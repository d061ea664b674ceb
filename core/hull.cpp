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
  // Orient every facet away from an interior point (the vertex centroid of the hull): robust
  // whatever the orientation of the mesh faces, and volumes are tetrahedra from that point.
  Vec3 o;
  for (auto v : m.vertices()) o += Vec3{m.point(v).x(), m.point(v).y(), m.point(v).z()};
  o = o / static_cast<double>(m.number_of_vertices());
  for (auto f : m.faces()) {
    std::vector<Vec3> poly;
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      const auto& p = m.point(v);
      poly.push_back({p.x(), p.y(), p.z()});
    }
    if (poly.size() < 3) continue;
    Vec3 area;
    for (size_t i = 1; i + 1 < poly.size(); ++i) area += cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
    const double len = norm(area);
    if (len <= 0) continue;
    Vec3 n = area / len;
    if (dot(n, poly[0] - o) < 0) n = -n;
    h.volume += std::abs(dot(poly[0] - o, area)) / 6.0;
    // A sliver facet's double normal can be tilted: push its plane out to the farthest point so
    // that every facet is a true supporting plane (the half-space still contains the hull).
    double far = -1e300;
    for (const Vec3& q : points) far = std::max(far, dot(n, q));
    h.facets.push_back({n, -far});
  }
  return h;
}

}  // namespace mc
