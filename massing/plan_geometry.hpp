// Plan (2D) geometry of the massing analytics: areas of polygons with holes, the width and length
// of a footprint's convex hull, and exact unions (GEOS through OGR).
#pragma once
#include <array>
#include <vector>

#include "io/gpkg_writer.hpp"

namespace mc::massing {

using Pt = std::array<double, 2>;

// Coordinates on a 1e-6 grid before any union: shared vertices of neighbouring parts are then
// exactly equal, and the result does not depend on the last bits of a projection.
double snap(double v);
double ring_signed_area(const mc::io::Ring2& r);
double polygon_area(const mc::io::Polygon2& p);  // outer ring minus holes
double multipolygon_area(const mc::io::MultiPolygon2& m);

// A convex polygon's width (the smallest distance between two parallel lines enclosing it) and its
// length (its extent along the direction of those lines): the sides of its narrowest enclosing
// rectangle.
struct PlanExtent {
  double width = 0, length = 0;
};
PlanExtent plan_extent(const mc::io::Ring2& hull);
// The convex hull of the outer rings' points.
mc::io::Ring2 outer_hull(const mc::io::MultiPolygon2& m);

// Exact union of polygons; empty with ok = false on failure.
mc::io::MultiPolygon2 union_of(const std::vector<mc::io::Polygon2>& polys, bool& ok);

}  // namespace mc::massing
