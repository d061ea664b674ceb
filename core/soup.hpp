// Cleaning, centring and triangulation of an input polygon soup (docs/algorithm.md §2).
// Real inputs are soups: duplicated and unused vertices, degenerate or repeated polygons,
// non-planar and self-touching rings. Everything downstream (segmentation, the oracle,
// Hausdorff) works on the cleaned mesh or on its triangles.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry.hpp"
#include "core/polygon_mesh.hpp"
#include "core/vec3.hpp"

namespace mc {

struct TriangleSoup {
  std::vector<Vec3> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint32_t> source_face;  // per triangle: index of the PolygonMesh face it came from
};

// Returns a cleaned copy of `mesh`:
//  - vertices with non-finite coordinates are dropped, with every face that uses them
//    (faces with out-of-range indices too);
//  - vertices closer than `merge_tol` are merged (grid hashing + union-find; the smallest
//    original index of a cluster gives the position, so the result is deterministic);
//  - repeated consecutive indices are removed; rings with < 3 distinct vertices or ~zero area
//    are dropped (a face whose outer ring goes is dropped with its holes);
//  - duplicate faces (same rings up to rotation and reversal) are dropped, the first is kept;
//  - unused vertices are removed (vertex order otherwise preserved).
// Each kind of removal adds one human-readable line to `problems` (when non-null).
PolygonMesh clean_soup(const PolygonMesh& mesh, double merge_tol, std::vector<std::string>* problems);

// Triangulates every face. Triangles keep the face's outer-ring orientation. Polygons with holes,
// non-convex and non-planar polygons are triangulated by a constrained Delaunay triangulation of
// their projection on the best-fit plane, keeping the odd-nesting (inside) domain. Constraint
// crossings (self-intersecting rings) create new vertices, appended after mesh.vertices.
TriangleSoup triangulate(const PolygonMesh& mesh);

// Centre of the axis-aligned bounding box of the vertices used by faces (all vertices when no
// face uses any); {0,0,0} for an empty mesh.
Vec3 bbox_center(const PolygonMesh& mesh);
void translate(PolygonMesh& mesh, Vec3 offset);

// Unit normal of the outer ring (zero vector when degenerate) and the face's area
// (outer area minus hole areas, as seen along the outer normal; never negative).
struct FaceGeometry {
  Vec3 normal;
  double area = 0;
};
FaceGeometry face_geometry(const PolygonMesh& mesh, const Polygon& face);

}  // namespace mc
