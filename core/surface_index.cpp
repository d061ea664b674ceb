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

}  // namespace mc
