// "Does the input surface pass through this box?" over the input triangles (CGAL AABB tree,
// exact triangle/box tests). Carving uses it to vote cheaply on cells the surface does not
// touch: such a cell is entirely inside or entirely outside.
#pragma once
#include <memory>

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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mc
