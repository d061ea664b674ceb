// Convex hull of a point set (CGAL quickhull on doubles, EPICK): its volume and facet planes.
// Measurement only, so the inexact-construction kernel is enough (docs/algorithm.md §9.2).
#pragma once
#include <vector>

#include "core/plane.hpp"
#include "core/vec3.hpp"

namespace mc {

struct Hull {
  double volume = 0;
  std::vector<Plane> facets;  // outward unit normals
};

Hull convex_hull(const std::vector<Vec3>& points);

}  // namespace mc
