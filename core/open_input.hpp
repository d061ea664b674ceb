// Open inputs (docs/algorithm.md §6.4, §6.5): how open a building's surface is, the surfaces the
// vertical "roof-over-ground" vote counts, the vertical planes of its open boundary (missing
// walls), and an estimate of the volume it encloses for the volume check.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "core/hole_planes.hpp"
#include "core/oracle.hpp"
#include "core/plane.hpp"
#include "core/polygon_mesh.hpp"
#include "core/soup.hpp"

namespace mc {

struct OpenInput {
  double boundary_length = 0;  // edges used by one ring
  // Boundary length not lying (within δ, collinear) along another boundary edge: T-junctions and
  // cracks between faces that meet geometrically are covered; the border of a missing face is not.
  // Edges in the lowest level (within δ) do not count: an open bottom is what the parity vote's
  // upward rays and the ground cap already handle (§6.1, §5).
  double uncovered_length = 0;
  std::vector<std::pair<Vec3, Vec3>> uncovered_edges;  // all of them, the lowest level's too
  size_t nonmanifold_edges = 0;  // edges used by 3+ rings (interior sheets glued to walls)
  bool semantics = false;        // some face has a semantic surface type
  bool has_ground =
      false;  // a GroundSurface, or (no semantics) a downward horizontal face at the lowest level
  bool open(double cell_size) const { return uncovered_length > 2 * cell_size; }
  // Whether the vertical vote can be trusted: it counts every non-vertical surface, so interior
  // sheets (edges of 3+ faces) break it unless semantics say which surfaces are interior.
  bool vertical_applicable() const { return nonmanifold_edges == 0 || semantics; }
};

// `mesh` cleaned (shared vertices welded), z-up.
OpenInput analyse_open_input(const PolygonMesh& mesh, double dist);

// Vertical planes through the uncovered boundary edges (the foot of a missing wall under a roof
// edge, the rim of a ground without walls), edges with the same plane (normals within
// `angle_rad`, within δ) grouped; groups shorter than `min_length` are left out. Each plane's box
// spans its edges horizontally (grown by δ) and [z_lo, z_hi] vertically; its area is the group's
// length times that height (the missing wall's size, which orders it among the regions).
std::vector<HolePlane> boundary_wall_planes(const OpenInput& open, double dist, double angle_rad,
                                            double min_length, double z_lo, double z_hi);

// Per triangle of `soup` (triangulated from `mesh`, source_face into mesh.faces): whether the
// vertical vote counts it. Semantics when the face has one (RoofSurface, GroundSurface and other
// outer surfaces yes; WallSurface, ClosureSurface, FloorSurface, CeilingSurface, InteriorWallSurface
// no), else geometry (not within ~3° of vertical).
std::vector<uint8_t> cover_triangles(const TriangleSoup& soup, const PolygonMesh& mesh);

// Floors of parts whose ground is missing above the building's lowest level (walls that start
// higher up, as on a slope; docs/algorithm.md §6.4): the hole loops (core/hole_planes) that are
// horizontal (within `angle_rad`) with a surface of `cover` (the vote's roofs and grounds) above
// their inside and no surface of `surface` (every input triangle, walls too) below it. Returned
// as triangles, for the vertical vote to count as ground faces: without them every column stands
// on the lowest height and a part on higher ground gains the air beneath it. (A storey junction
// over an inclined wall, as in a tower of inclined prisms, has that wall below it: no floor.)
TriangleSoup open_bottoms(const std::vector<HolePlane>& holes, const VerticalOracle& cover,
                          const VerticalOracle& surface, double dist, double angle_rad);

// |signed volume| of the soup when it is closed and consistently oriented (every edge traversed
// as often in each direction); -1 otherwise.
double closed_volume(const TriangleSoup& soup);

}  // namespace mc
