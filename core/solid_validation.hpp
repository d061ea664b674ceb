// Validity of one Solid (one closed shell as a polygon mesh in real coordinates), checked in
// val3dity's hierarchy: rings (1xx), polygons (2xx), shell (3xx). Codes and names are val3dity's
// (ISO 19107 rules), so a report can be compared with that tool's.
// CGAL lives only in solid_validation.cpp (compile time).
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/plane.hpp"
#include "core/polygon_mesh.hpp"

namespace mc {

struct SolidError {
  int code = 0;
  std::string name;     // e.g. "SHELL_NOT_CLOSED"
  std::string message;  // what and where (face index, coordinates, measured value)
};

// val3dity's codes used here (val3dity 2.6's numbering).
namespace solid_code {
constexpr int kTooFewPoints = 101, kConsecutivePointsSame = 102, kRingSelfIntersection = 104,
              kRingCollapsed = 105, kIntersectionRings = 201, kNonPlanarPolygon = 203,
              kNonPlanarNormals = 204, kInteriorDisconnected = 205, kInnerRingOutside = 206,
              kInnerRingsNested = 207, kOrientationRingsSame = 208, kNotValid2Manifold = 300,
              kTooFewPolygons = 301, kShellNotClosed = 302, kNonManifoldCase = 303, kMultipleComponents = 305,
              kShellSelfIntersection = 306, kPolygonWrongOrientation = 307, kWrongOrientationShell = 405;
}
const char* solid_error_name(int code);

struct SolidTolerances {
  double snap = 1e-6;       // vertices this close are one vertex (m): distance <= snap
  double planarity = 1e-3;  // max distance of a face's points to its least-squares plane (m)
  // Max angle (degrees) between the normals of the triangles of one face, triangulated in its
  // least-squares plane (val3dity's 204 rule); 0 = not checked. With it, rings are also checked
  // for simplicity in that plane's projection (val3dity's 104 rule: a ring touching itself at a
  // vertex, or collapsed to a line) and faces with holes by val3dity's (GEOS's) polygon rules
  // (201, 205, 206, 207). docs/output-format.md §Validity.
  double normals_deg = 0;
  // val3dity's own merge test instead of distance <= snap: squared distance < snap² on the
  // coordinates as given, each vertex merged into the first earlier one that is that close.
  // Vertices exactly one grid step apart (1 mm at a 1 mm grid) are then merged or not as the
  // file's coordinates round, as val3dity does (`morphcut-city validate`).
  bool snap_strict = false;
  // > 0: the solid must also be valid with vertices merged only up to this distance. The writer
  // checks in a metric frame before the coordinates are written in the file's CRS, so it cannot
  // know how val3dity will round a pair exactly at the snap distance: it wants parts valid both
  // with such pairs merged (`snap`) and apart (`snap_apart`).
  double snap_apart = 0;
};
// Vertices within `snap` of each other become one, in the order given: each vertex joins the
// first earlier merged vertex that close (val3dity's Surface::add_point), else starts a new one.
// `strict`: squared distance < snap² (val3dity's comparison), else distance <= snap. Returns each
// vertex's merged index; `merged` gets the merged positions.
std::vector<uint32_t> merge_vertices(const std::vector<Vec3>& v, double snap, std::vector<Vec3>& merged,
                                     bool strict = false);

// val3dity's default tolerances as the writer applies them: vertices up to 1 mm apart are one
// vertex (a comparison on rounded coordinates decides exactly 1 mm either way, so a part must be
// valid with vertices 1 mm apart merged and kept apart). Every written part passes them.
inline SolidTolerances val3dity_tolerances() {
  return {0.001 * (1 + 1e-6), 0.01, 20, false, 0.001 * (1 - 1e-6)};
}
// val3dity's default tolerances and its own merge test, to report what val3dity reports on the
// coordinates of a file (`morphcut-city validate`).
inline SolidTolerances val3dity_exact_tolerances() { return {0.001, 0.01, 20, true, 0}; }

// The shell as triangles over merged vertices (faces triangulated in their plane, holes kept),
// oriented like the input faces.
struct TriangleShell {
  std::vector<Vec3> points;
  std::vector<std::array<uint32_t, 3>> triangles;
};

struct SolidCheck {
  std::vector<SolidError> errors;  // empty = valid
  // Input faces (indices into PolygonMesh::faces) that break a face rule (1xx, 2xx), with the
  // code: what a repair has to redo.
  std::vector<std::pair<size_t, int>> bad_faces;
  // A closed, 2-manifold, outward-oriented shell without self-intersection (its faces may be
  // non-planar beyond the tolerance): volume and common_volume are meaningful.
  bool closed_manifold = false;
  double volume = 0;       // signed (negative = inward normals), m³
  double area = 0;         // m²
  double hull_volume = 0;  // of the convex hull, m³
  double convexity = 0;    // volume / hull_volume
  BBox box;
  std::vector<Plane> hull_facets;  // outward unit normals
  TriangleShell shell;
  bool valid() const { return errors.empty(); }
};

// `measures` = false skips the convex hull (hull_volume, hull_facets, convexity stay 0).
SolidCheck check_solid(const PolygonMesh& solid, const SolidTolerances& tol = {}, bool measures = true);

// One polygon (outer ring and holes, indices into `pts`) triangulated in its plane (constrained
// Delaunay, holes left out); triangles turn like the outer ring. False when its rings cross.
bool triangulate_polygon(const std::vector<std::vector<uint32_t>>& rings, const std::vector<Vec3>& pts,
                         std::vector<std::array<uint32_t, 3>>& out);
// The same, canonical: projected by dropping the dominant axis of the outer ring's normal (no
// arithmetic on the coordinates) and with the points inserted in index order, so that a polygon
// and its reversed twin (the face two parts share) get the same triangles. Triangles turn like
// the outer ring.
bool triangulate_polygon_canonical(const std::vector<std::vector<uint32_t>>& rings,
                                   const std::vector<Vec3>& pts, std::vector<std::array<uint32_t, 3>>& out);
// Do the points lie exactly on one plane (exact predicates on the doubles)?
bool exactly_coplanar(const std::vector<Vec3>& pts);

// What two solids with closed_manifold have in common: its volume (m³; 0 when they only touch)
// and surface area (m²; 2 x volume / area is the mean thickness, which tells a sliver from a real
// overlap). nullopt when the exact boolean operation cannot build a closed result (then the
// caller must say so, not guess).
struct Common {
  double volume = 0, area = 0;
};
std::optional<Common> common_volume(const TriangleShell& a, const TriangleShell& b);
// Do the interiors of two solids with closed_manifold intersect? val3dity's BUILDINGPARTS_OVERLAP
// test (601), exact on the coordinates as given: any common volume, however thin. `exact_tests`
// counts the pairs that needed exact constructions (the others are told apart by their boxes or
// a convex hull facet with exact predicates).
bool interiors_overlap(const TriangleShell& a, const TriangleShell& b, size_t* exact_tests = nullptr);
// Does the plane through p, q, r (not collinear) have all of `a` on one closed side and all of `b`
// on the other (exact predicates)? Then their interiors are apart: two parts on either side of a
// face they share, the cheap test before interiors_overlap.
// The outward facets of the convex hull of `points` (their corners are input points), and whether
// one of them has all of `other` on its closed outer side (exact predicates): the hull test of
// interiors_overlap, with each part's hull built once when a level tests many pairs.
std::vector<std::array<Vec3, 3>> hull_facets(const std::vector<Vec3>& points);
bool facet_separates(const std::vector<std::array<Vec3, 3>>& facets, const std::vector<Vec3>& other);
// interiors_overlap without its box and hull filters (the exact boolean alone).
bool interiors_overlap_exact(const TriangleShell& a, const TriangleShell& b);
// Is every point of `a` that is not a point of `b` farther than `d` from every triangle of `b`?
// (Floating point; for a margin of whole grid steps.)
bool min_distance_beyond(const TriangleShell& a, const TriangleShell& b, double d);
bool plane_separates(const Vec3& p, const Vec3& q, const Vec3& r, const std::vector<Vec3>& a,
                     const std::vector<Vec3>& b);
// The fallback common_volume uses when the boolean's result is not a 2-manifold: both shells
// corefined, the faces bounding the common part picked and integrated (divergence theorem). When
// the picked faces do not close up (near-coplanar contact; detected as a result that depends on
// the origin) the volume is estimated by sampling a grid of 2·10^5 points instead.
std::optional<Common> common_volume_by_faces(const TriangleShell& a, const TriangleShell& b);

}  // namespace mc
