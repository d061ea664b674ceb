#include "core/surface_index.hpp"

#include "core/aabb_triangles.hpp"

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

bool SurfaceIndex::enters(const std::vector<Plane>& outward, const BBox& b, double depth) const {
  if (impl_->triangles.empty()) return false;
  std::vector<Tree::Primitive_id> near;
  impl_->tree.all_intersected_primitives(CGAL::Bbox_3(b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z),
                                         std::back_inserter(near));
  std::vector<Vec3> poly, next;
  for (const auto& id : near) {
    const K::Triangle_3& t = *id;
    poly.clear();
    for (int k = 0; k < 3; ++k) poly.push_back({t[k].x(), t[k].y(), t[k].z()});
    // Clip to the region shrunk by `depth` (Sutherland–Hodgman, one plane at a time).
    for (const Plane& pl : outward) {
      next.clear();
      for (size_t i = 0; i < poly.size(); ++i) {
        const Vec3& a = poly[i];
        const Vec3& c = poly[(i + 1) % poly.size()];
        const double da = pl.signed_distance(a) + depth, dc = pl.signed_distance(c) + depth;
        if (da <= 0) next.push_back(a);
        if ((da < 0 && dc > 0) || (da > 0 && dc < 0)) next.push_back(a + (c - a) * (da / (da - dc)));
      }
      poly.swap(next);
      if (poly.size() < 3) break;
    }
    if (poly.size() < 3) continue;
    Vec3 area;
    for (size_t i = 1; i + 1 < poly.size(); ++i) area += cross(poly[i] - poly[0], poly[i + 1] - poly[0]);
    if (norm(area) > 0) return true;
  }
  return false;
}

}  // namespace mc
