// From a CityJSON feature to the algorithm's input: one polygon soup per building.
#pragma once
#include <string>
#include <vector>

#include "core/polygon_mesh.hpp"
#include "io/cityjson_types.hpp"

namespace mc::io {

struct BuildingInput {
  std::string id;
  std::string lod;  // the LoD actually used (as written in the file); empty when none
  mc::PolygonMesh mesh;
  std::vector<std::string> problems;  // the feature's read problems, then extraction problems
};

// True when the feature's top-level object is a "Building" (extension types such as
// "+NoiseBuilding" are not buildings for us).
bool is_building(const Feature& f);

// The Building's own geometry plus that of its BuildingParts (recursively) at LoD `lod`: an exact
// string match ("2.2", "2", "2.0" are different), or "highest" = the numerically highest LoD among
// them. All shells and surfaces of Solid, CompositeSolid, MultiSolid, MultiSurface and
// CompositeSurface (and GeometryInstances of those, via the header's geometry-templates) go into
// ONE polygon soup with holes and semantic surface types. Bad faces/geometries are skipped with a
// problem naming the object; this never throws on bad data.
BuildingInput extract_building(const Feature& f, const Header& h, const std::string& lod = "highest");

// The distinct LoDs of the building's surface geometries, in first-seen order.
std::vector<std::string> building_lods(const Feature& f, const Header& h);

// Removes the geometries extract_building(f, h, lod) decomposes (`lod` as it reported it, e.g.
// "2.2"; numerically equal LoDs alike) from the Building and its BuildingParts, except from
// BuildingParts a morphcut run added (attribute `morphcut_level`). A level output puts that
// level's parts in their place (docs/output-format.md). Returns the number removed.
size_t remove_geometries_at_lod(Feature& f, const Header& h, const std::string& lod);

}  // namespace mc::io
