// "Does the input surface pass through this box?" over the input triangles (CGAL AABB tree,
// exact triangle/box tests). Carving uses it to vote cheaply on cells the surface does not
// touch (such a cell is entirely inside or entirely outside) or only grazes along its facets.
#pragma once
#include <cstdint>
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
  // The input triangles (ids, ascending) that intersect the closed box.
  std::vector<uint32_t> touching(const BBox& box) const;
  // Those of `among` (ids from `touching`) that intersect the closed box, in order, into `out`:
  // nested boxes narrow the list instead of querying the tree again.
  void touching(const BBox& box, const std::vector<uint32_t>& among, std::vector<uint32_t>& out) const;
  // Whether every vertex of the triangles `ids` lies within `eps` of one plane (that of the
  // largest of them), returned in `plane`; false for an empty list.
  bool common_plane(const std::vector<uint32_t>& ids, double eps, Plane& plane) const;
  // True when some input triangle reaches more than `depth` into the convex region
  // {x : n·x + d <= 0 for every plane of `outward`} whose box is `box` (triangles clipped in
  // doubles). A triangle lying along the region's boundary, within `depth` of it, does not.
  bool enters(const std::vector<Plane>& outward, const BBox& box, double depth) const;
  // The same for the triangles `near` (ids from `touching` the region's box): one query of the
  // tree serves several tests of a region.
  bool enters(const std::vector<Plane>& outward, const std::vector<uint32_t>& near, double depth) const;
  // The triangles (ids, ascending) that reach more than `depth` into that region: those that do
  // not lie along its boundary, within `depth` of it.
  std::vector<uint32_t> entering(const std::vector<Plane>& outward, const BBox& box, double depth) const;
  // The same among the triangles `near` (ids from `touching` the region's box, ascending).
  std::vector<uint32_t> entering(const std::vector<Plane>& outward, const std::vector<uint32_t>& near,
                                 double depth) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mc
