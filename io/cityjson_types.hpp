// The data types the CityJSON reader hands out and the writer takes back.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/vec3.hpp"
#include "core/working_frame.hpp"

namespace mc::io {

// A self-contained unit of a city: one top-level CityObject with all its descendants (a Building
// with its BuildingParts, ...), like a CityJSONFeature.
struct Feature {
  std::string id;                     // the top-level object's id
  nlohmann::json objects;             // id -> CityObject JSON as in the input, except that geometry
                                      // "boundaries" index into `vertices` below (-1 = bad reference)
  std::vector<mc::Vec3> vertices;     // real-world coordinates (transform already applied)
  std::vector<std::string> problems;  // per-object problems found while reading
  // Other members of a CityJSONFeature line (e.g. an "appearance" local to the feature);
  // null for features read from a .city.json, where such members live in the header.
  nlohmann::json extra;
};

struct Header {
  std::string version;  // "1.0", "1.1" or "2.0"
  // Every root member except CityObjects and vertices (type, version, transform, metadata,
  // extensions, appearance, geometry-templates, extra root properties, ...).
  nlohmann::json root = nlohmann::json::object();
  std::string crs;  // e.g. "EPSG:7415" from metadata.referenceSystem; empty if none
  // What the coordinates are (io/crs.hpp: coordinate_system): metres unless the CRS says otherwise.
  mc::CoordinateSystem coords;
  std::string coords_note;  // why the coordinates are assumed metric although a CRS is given
};

}  // namespace mc::io
