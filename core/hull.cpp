#include "core/hull.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/Filtered_predicate.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/union_find.hpp"

namespace mc {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

// CGAL's hull traits with both of quickhull's predicates exact through Mpzf, CGAL's exact float
// for ring-only predicates, instead of GMP rationals. Building points are often exactly coplanar
// (a wall's corners) or exactly as far from a facet (a roof's ridge), so the floating-point
// filters fail and the exact fallback ran about half of the hull's time in GMP's rationals. The
// answers are the same exact signs, so the hull is the same (docs/benchmarks.md, "Speed").
//  - Is the point above a facet: the kernel's Orientation_3 (statically filtered, exact in Mpzf),
//    which quickhull uses for any traits but CGAL's own filtered one.
//  - Which of two points is farther from a facet: the sign of one 3x3 determinant, intervals
//    first, then Mpzf.
struct HullTraits : CGAL::Convex_hull_traits_3<K, Mesh> {
  using EK = CGAL::Simple_cartesian<CGAL::Mpzf>;
  using AK = CGAL::Simple_cartesian<CGAL::Interval_nt_advanced>;
  using LessDistance =
      CGAL::Filtered_predicate<EK::Less_signed_distance_to_plane_3, AK::Less_signed_distance_to_plane_3,
                               CGAL::Cartesian_converter<K, EK>, CGAL::Cartesian_converter<K, AK>>;
  struct Less_signed_distance_to_plane_3 {
    bool operator()(const Plane_3& h, const Point_3& p, const Point_3& q) const {
      return LessDistance()(h.p(), h.q(), h.r(), p, q);
    }
  };
  Less_signed_distance_to_plane_3 less_signed_distance_to_plane_3_object() const { return {}; }
};

}  // namespace

Hull convex_hull(const std::vector<Vec3>& points) {
  Hull h;
  if (points.size() < 4) return h;
  std::vector<K::Point_3> pts;
  pts.reserve(points.size());
  for (const Vec3& p : points) pts.emplace_back(p.x, p.y, p.z);
  Mesh m;
  CGAL::convex_hull_3(pts.begin(), pts.end(), m, HullTraits());
  if (m.number_of_faces() < 4) return h;  // coplanar input: no volume
  // CGAL triangulates a facet with four or more coplanar points in an order that depends on memory
  // addresses, and so did the last bit of the volume (two runs of a sample with two threads
  // reported different hull volumes). So triangles are first grouped into the hull's true facets
  // (exact coplanarity across their shared edges), and everything below is computed from vertex
  // sets alone, whatever the order of the input: the interior point is the mean of the hull's
  // vertices in lexicographic order, a facet's vertices are put in angular order starting from
  // the lexicographically smallest, and volumes and facets are sorted.
  UnionFind up(m.number_of_faces());
  for (auto e : m.edges()) {
    const auto he = m.halfedge(e);
    const auto f1 = m.face(he), f2 = m.face(m.opposite(he));
    if (f1 == Mesh::null_face() || f2 == Mesh::null_face()) continue;
    const auto& a = m.point(m.source(he));
    const auto& b = m.point(m.target(he));
    const auto& c = m.point(m.target(m.next(he)));
    const auto& d = m.point(m.target(m.next(m.opposite(he))));
    if (CGAL::coplanar(a, b, c, d)) up.link(uint32_t(f1.idx()), uint32_t(f2.idx()));
  }
  auto less = [](const Vec3& a, const Vec3& b) {
    return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
  };
  std::vector<std::vector<Vec3>> groups(up.size());
  for (auto f : m.faces())
    for (auto v : CGAL::vertices_around_face(m.halfedge(f), m)) {
      const auto& p = m.point(v);
      groups[up.find(uint32_t(f.idx()))].push_back({p.x(), p.y(), p.z()});
    }
  // Interior point: the mean of the hull's vertices in lexicographic order.
  std::vector<Vec3> corners;
  for (auto v : m.vertices()) corners.push_back({m.point(v).x(), m.point(v).y(), m.point(v).z()});
  std::sort(corners.begin(), corners.end(), less);
  Vec3 o;
  for (const Vec3& p : corners) o += p;
  o = o / static_cast<double>(corners.size());
  std::vector<double> parts;
  std::vector<std::pair<std::vector<Vec3>, Plane>> facets;
  for (std::vector<Vec3>& poly : groups) {
    std::sort(poly.begin(), poly.end(), less);
    poly.erase(std::unique(poly.begin(), poly.end()), poly.end());
    if (poly.size() < 3) continue;
    // Facet normal from the vertex set: the widest triangle on the smallest vertex, outward.
    Vec3 n;
    double best = 0;
    for (size_t i = 1; i < poly.size(); ++i)
      for (size_t j = i + 1; j < poly.size(); ++j) {
        const Vec3 c = cross(poly[i] - poly[0], poly[j] - poly[0]);
        if (norm(c) > best) best = norm(c), n = c;
      }
    if (best <= 0) continue;
    n = n / best;
    if (dot(n, poly[0] - o) < 0) n = -n;
    // Counter-clockwise about n around the vertices' mean, starting at the smallest vertex.
    Vec3 mid;
    for (const Vec3& p : poly) mid += p;
    mid = mid / static_cast<double>(poly.size());
    const Vec3 u = poly[0] - mid, w = cross(n, u);
    std::vector<std::pair<double, Vec3>> ring;
    for (const Vec3& p : poly) ring.push_back({std::atan2(dot(p - mid, w), dot(p - mid, u)), p});
    std::sort(ring.begin(), ring.end(), [&](const auto& a, const auto& b) { return a.first < b.first; });
    for (size_t i = 0; i < ring.size(); ++i) poly[i] = ring[i].second;
    std::rotate(poly.begin(), std::min_element(poly.begin(), poly.end(), less), poly.end());
    Vec3 area;
    for (size_t i = 1; i + 1 < poly.size(); ++i) area += cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
    const double len = norm(area);
    if (len <= 0) continue;
    n = area / len;
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

std::vector<std::array<double, 2>> convex_hull_2d(std::vector<std::array<double, 2>> pts) {
  using P = std::array<double, 2>;
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return pts;
  auto cross = [](const P& o, const P& a, const P& b) {
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  };
  std::vector<P> h(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && cross(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  return h;
}

}  // namespace mc
