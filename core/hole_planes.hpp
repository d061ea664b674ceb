// Planes that close holes of an open input (a missing wall or roof face): each boundary loop of
// the soup that is planar within δ and encloses at least the region area limit gives the plane
// of the missing face. Without it the carving has no plane there, and the cell runs on to the
// next plane or to the padded box (a missing front wall let a gable house's cell grow 1 m out).
// The open bottom (walls without a floor) is such a loop too; preprocessing caps it separately
// with the ground plane, so loops lying in the input's lowest level are left out; so are horizontal
// loops along the lower edges of walls that stop above a ground (a gap, docs/algorithm.md §5).
#pragma once
#include <vector>

#include "core/plane.hpp"
#include "core/polygon_mesh.hpp"

namespace mc {

struct HolePlane {
  Plane plane;
  BBox bbox;               // of the loop's vertices
  double area;             // enclosed by the loop
  std::vector<Vec3> loop;  // the loop's vertices in order (empty for planes not from a loop)
};

// `mesh` must be cleaned (clean_soup: shared vertices welded). Edges used by exactly one face
// ring are boundary edges; only components of the boundary graph that form one simple cycle
// are loops. Deterministic (loops in order of their smallest vertex index).
std::vector<HolePlane> hole_planes(const PolygonMesh& mesh, double dist, double min_area, double lowest_z);

}  // namespace mc
