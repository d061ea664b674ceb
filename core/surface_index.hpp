// "Does the input surface pass through this box?" over the input triangles (CGAL AABB tree,
// exact triangle/box tests). Carving uses it to vote cheaply on cells the surface does not
// touch (such a cell is entirely inside or entirely outside) or only grazes along its facets.
#pragma once
#include <memory>
#include <vector>

#include "core/plane.hpp"
#include "core/soup.hpp"

namespace mc {

class SurfaceIndex {
 public:
  explicit SurfaceIndex(const TriangleSoup& soup);
  ~SurfaceIndex();
  SurfaceIndex(const SurfaceIndex&) = delete;
  SurfaceIndex& operator=(const SurfaceIndex&) = delete;
  // True when some input triangle intersects the (closed) box.
  bool touches(const BBox& box) const;
  // True when some input triangle reaches more than `depth` into the convex region
  // {x : n·x + d <= 0 for every plane of `outward`} whose box is `box` (triangles clipped in
  // doubles). A triangle lying along the region's boundary, within `depth` of it, does not.
  bool enters(const std::vector<Plane>& outward, const BBox& box, double depth) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mc
