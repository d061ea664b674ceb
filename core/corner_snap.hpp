// Corner snapping: fitted planes that should meet in one corner really meet there.
//
// Where four or more input faces of different planes share a vertex (a roof valley's eave
// corner: two walls and two roof slopes), their fitted planes miss a common point by fitting
// noise. The carving then finds a vertex a hair from a plane and refuses that plane (vertices a
// hair apart collapse when the output is quantised), so a wing roof stays a box. Instead, the
// three best-conditioned, largest planes at the corner define its exact point, and each further
// plane passing within `tol` of it is anchored there (PlaneRegistry::set_anchor): the exact
// complex builds it through that point, so the corner is one vertex and no hair is left.
// Snapping moves a plane by at most `tol` at the corner; a plane is anchored at most once (the
// first corner in vertex order) and never to planes that depend on it (no cycles).
#pragma once
#include <cstdint>
#include <vector>

#include "core/plane.hpp"
#include "core/polygon_mesh.hpp"
#include "core/segmentation.hpp"

namespace mc {

// `region_plane[i]` is the registry id of regions[i]'s plane. Returns the number of anchored
// planes. Deterministic (corners in order of their position).
size_t snap_corners(const PolygonMesh& mesh, const std::vector<PlaneRegion>& regions,
                    const std::vector<uint32_t>& region_plane, PlaneRegistry& registry, double tol);

// Line snapping, for the planes of missing faces (hole and open-boundary planes: not fitted, they
// go through input edges). Such a plane passing within `tol` of the line where two region planes
// meet, without containing it, is refused by the carving's hair rule in every cell that line
// bounds, and a wedge of air or of the building stays mislabelled (docs/algorithm.md §7.4). It is
// anchored on the nearest such line instead (PlaneRegistry::set_line_anchor), which moves it by at
// most `tol` there. Only lines parallel to the plane (within 10⁻⁶ rad) that pass through its box
// (`boxes[i]` for `planes[i]`, grown by `grow`) count. Returns the number of planes anchored.
size_t snap_to_lines(const std::vector<uint32_t>& planes, const std::vector<BBox>& boxes,
                     const std::vector<uint32_t>& region_plane, PlaneRegistry& registry, double tol,
                     double grow);

}  // namespace mc
