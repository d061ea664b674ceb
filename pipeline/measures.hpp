// Plain geometric measurements of polygon meshes for the reports and the planners' CSV.
// Everything is double arithmetic on real-world coordinates, taken relative to a local origin so
// that RD/UTM coordinates (1e5..1e6 m) do not eat the precision of the small differences.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/polygon_mesh.hpp"
#include "core/vec3.hpp"

namespace mc::pipeline {

struct VolumeCentroid {
  double volume = 0;  // signed: positive for an outward-oriented closed surface
  Vec3 centroid;      // of the solid (meaningful for a closed surface with volume != 0)
};

// Divergence theorem over every ring fan-triangulated from its first vertex. Exact for planar
// polygons whether convex or not; holes (opposite orientation) subtract as they should.
VolumeCentroid volume_centroid(const PolygonMesh& m);
// Sums over several meshes (e.g. all parts of one level = the whole building).
VolumeCentroid volume_centroid(const std::vector<PolygonMesh>& ms);

// Area of the polygon (outer ring minus holes) projected onto the xy plane, unsigned.
double projected_area(const PolygonMesh& m, const Polygon& p);

// Area of the 2D convex hull of the xy projection of `points` (Andrew's monotone chain).
double hull_area_2d(const std::vector<Vec3>& points);

struct Footprint {
  double area = 0;
  // "ground": projected area of the GroundSurface faces; "hull": 2D convex hull of all
  // vertices, used when the input has no GroundSurface (e.g. unlabelled LoD1 blocks).
  std::string method;
};
Footprint footprint(const PolygonMesh& input);

// max z - min z of the vertices that faces use; nullopt when there are none.
std::optional<double> height(const PolygonMesh& m);
// Centre of the bounding box of the used vertices; nullopt when there are none.
std::optional<Vec3> bbox_centre(const PolygonMesh& m);

}  // namespace mc::pipeline
