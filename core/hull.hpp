// Convex hull of a point set (CGAL quickhull on doubles, EPICK): its volume and facet planes.
// Measurement only, so the inexact-construction kernel is enough (docs/algorithm.md §9.2).
#pragma once
#include <array>
#include <vector>

#include "core/plane.hpp"
#include "core/vec3.hpp"

namespace mc {

struct Hull {
  double volume = 0;
  std::vector<Plane> facets;  // outward unit normals
};

Hull convex_hull(const std::vector<Vec3>& points);

// Convex hull of points in the plane (Andrew's monotone chain): counter-clockwise, without
// collinear or repeated points; fewer than 3 distinct points come back as they are (sorted).
std::vector<std::array<double, 2>> convex_hull_2d(std::vector<std::array<double, 2>> points);

}  // namespace mc
