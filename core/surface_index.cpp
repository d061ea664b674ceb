#include "core/surface_index.hpp"

#include "core/aabb_triangles.hpp"

#include <algorithm>
#include <cmath>

namespace mc {

using aabb::K;
using aabb::Tree;
using aabb::Triangles;

struct SurfaceIndex::Impl {
  Triangles triangles;
  Tree tree;
};

SurfaceIndex::SurfaceIndex(const TriangleSoup& soup) : impl_(std::make_unique<Impl>()) {
  for (const auto& t : soup.triangles) {
    const Vec3 &a = soup.vertices[t[0]], &b = soup.vertices[t[1]], &c = soup.vertices[t[2]];
    K::Triangle_3 tri({a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z});
    if (!tri.is_degenerate()) impl_->triangles.push_back(tri);
  }
  impl_->tree.insert(impl_->triangles.begin(), impl_->triangles.end());
  impl_->tree.build();
}

SurfaceIndex::~SurfaceIndex() = default;

bool SurfaceIndex::touches(const BBox& b) const {
  if (impl_->triangles.empty()) return false;
  return impl_->tree.do_intersect(CGAL::Bbox_3(b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z));
}

std::vector<uint32_t> SurfaceIndex::touching(const BBox& b) const {
  std::vector<uint32_t> ids;
  if (impl_->triangles.empty()) return ids;
  std::vector<Tree::Primitive_id> hit;
  impl_->tree.all_intersected_primitives(CGAL::Bbox_3(b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z),
                                         std::back_inserter(hit));
  for (const auto& id : hit) ids.push_back(static_cast<uint32_t>(id - impl_->triangles.begin()));
  std::sort(ids.begin(), ids.end());
  return ids;
}

void SurfaceIndex::touching(const BBox& b, const std::vector<uint32_t>& among,
                            std::vector<uint32_t>& out) const {
  out.clear();
  const CGAL::Bbox_3 box(b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z);
  for (uint32_t i : among) {
    const K::Triangle_3& t = impl_->triangles[i];
    if (CGAL::do_overlap(t.bbox(), box) && CGAL::do_intersect(t, box)) out.push_back(i);
  }
}

bool SurfaceIndex::common_plane(const std::vector<uint32_t>& ids, double eps, Plane& plane) const {
  if (ids.empty()) return false;
  auto vec = [](const K::Point_3& q) { return Vec3{q.x(), q.y(), q.z()}; };
  double best = -1;
  Vec3 normal, at;
  for (uint32_t i : ids) {
    const K::Triangle_3& t = impl_->triangles[i];
    const Vec3 a = vec(t[0]), n = cross(vec(t[1]) - a, vec(t[2]) - a);
    if (norm(n) > best) best = norm(n), normal = n, at = a;
  }
  if (!(best > 0)) return false;
  plane.n = normal * (1 / best);
  plane.d = -dot(plane.n, at);
  for (uint32_t i : ids)
    for (int k = 0; k < 3; ++k)
      if (std::abs(plane.signed_distance(vec(impl_->triangles[i][k]))) > eps) return false;
  return true;
}

namespace {

// Does triangle t reach more than `depth` into the convex region {x : n·x + d <= 0 for every
// plane of `outward`}? Clipped in doubles (Sutherland–Hodgman, one plane at a time), it keeps an
// area inside the region shrunk by `depth`.
bool triangle_enters(const K::Triangle_3& t, const std::vector<Plane>& outward, double depth,
                     std::vector<Vec3>& poly, std::vector<Vec3>& next) {
  poly.clear();
  for (int k = 0; k < 3; ++k) poly.push_back({t[k].x(), t[k].y(), t[k].z()});
  for (const Plane& pl : outward) {
    next.clear();
    // Each vertex's distance once: an edge's end is the next edge's start.
    const double d0 = pl.signed_distance(poly[0]) + depth;
    double da = d0;
    for (size_t i = 0; i < poly.size(); ++i) {
      const Vec3& a = poly[i];
      const bool last = i + 1 == poly.size();
      const Vec3& c = poly[last ? 0 : i + 1];
      const double dc = last ? d0 : pl.signed_distance(c) + depth;
      if (da <= 0) next.push_back(a);
      if ((da < 0 && dc > 0) || (da > 0 && dc < 0)) next.push_back(a + (c - a) * (da / (da - dc)));
      da = dc;
    }
    poly.swap(next);
    if (poly.size() < 3) return false;
  }
  Vec3 area;
  for (size_t i = 1; i + 1 < poly.size(); ++i) area += cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
  return norm(area) > 0;
}

}  // namespace

bool SurfaceIndex::enters(const std::vector<Plane>& outward, const BBox& b, double depth) const {
  if (impl_->triangles.empty()) return false;
  std::vector<Tree::Primitive_id> near;
  impl_->tree.all_intersected_primitives(CGAL::Bbox_3(b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z),
                                         std::back_inserter(near));
  std::vector<Vec3> poly, next;
  for (const auto& id : near)
    if (triangle_enters(*id, outward, depth, poly, next)) return true;
  return false;
}

bool SurfaceIndex::enters(const std::vector<Plane>& outward, const std::vector<uint32_t>& near,
                          double depth) const {
  std::vector<Vec3> poly, next;
  return std::any_of(near.begin(), near.end(), [&](uint32_t i) {
    return triangle_enters(impl_->triangles[i], outward, depth, poly, next);
  });
}

std::vector<uint32_t> SurfaceIndex::entering(const std::vector<Plane>& outward, const BBox& b,
                                             double depth) const {
  return entering(outward, touching(b), depth);
}

std::vector<uint32_t> SurfaceIndex::entering(const std::vector<Plane>& outward,
                                             const std::vector<uint32_t>& near, double depth) const {
  std::vector<uint32_t> ids;
  std::vector<Vec3> poly, next;
  for (uint32_t i : near)
    if (triangle_enters(impl_->triangles[i], outward, depth, poly, next)) ids.push_back(i);
  return ids;
}

}  // namespace mc
