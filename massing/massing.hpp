// Massing analytics (docs/massing.md): per level, each part's vertical extent,
// footprint, hull volume, ground contact and contacts with its neighbours (shared area and kind);
// a role per part by ordered rules; building features at the analysis level (massing.level).
// Pure functions of a level's part meshes (input coordinates), so deterministic.
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/params.hpp"
#include "core/polygon_mesh.hpp"
#include "core/working_frame.hpp"
#include "io/gpkg_writer.hpp"

namespace mc {
struct PartResult;
}

namespace mc::massing {

// One neighbour of a part: the faces they share, by their orientation.
struct Contact {
  uint32_t other = 0;  // part index in the level
  double area = 0;     // total shared face area
  std::string kind;    // "stacked", "side" or "inclined" (the kind with the largest area)
  int above = 0;       // stacked/inclined: +1 this part lies above the other, -1 below; side: 0
};

// A contact's faces summed by kind: kind -> (area, area with this part above minus area below).
using KindAreas = std::map<std::string, std::pair<double, double>>;
// The contact with `other` from those sums: the kind with the largest area, the side of the
// stacked or inclined contact by the sign of its signed area.
Contact contact_from(uint32_t other, const KindAreas& kinds);

// One of a part's own sloped roof faces (neither a wall nor flat, not shared with another part):
// its plane and area.
struct RoofFace {
  Vec3 normal;  // unit, upward
  Vec3 point;   // a vertex of the face
  double area = 0;
};

struct PartMassing {
  double z_min = 0, z_max = 0;
  double footprint_area = 0;  // vertical projection
  double width = 0;           // smallest caliper width of the footprint's convex hull
  double length = 0;          // its extent across that width (massing/plan_geometry.hpp)
  double volume = 0, hull_volume = 0, convexity = 0;
  // Share of the part's own faces (not shared with a neighbour) that are walls (within
  // side_angle_deg of vertical), by area: a roof piece has few, a dormer or a storey many.
  double wall_share = 0;
  // Share of the footprint covered by horizontal upward faces (own or shared) in the top quarter
  // of its height (at least mass_height_tolerance): 1 for a flat top, less for a low step.
  double flat_top = 0;
  bool grounded = false;
  std::vector<RoofFace> sloped_roof;  // its own sloped roof faces (a slice's test, masses.cpp)
  std::string role;                   // its mass's: main, wing, annex, podium, tower, roof, setback, rooftop
  int mass = -1;                      // index into LevelMassing::masses
  std::string piece = "body";         // body, roof (a roof piece of its mass) or layer (a thin skin)
  std::vector<Contact> contacts;      // by neighbour index
  mc::io::MultiPolygon2 footprint;
};

// Parts a person sees as one volume (docs/massing.md, "Masses").
struct MassMassing {
  std::vector<uint32_t> parts;  // ascending
  double z_min = 0, z_max = 0, volume = 0, hull_volume = 0, footprint_area = 0, width = 0, length = 0;
  bool grounded = false;
  std::string role;
  std::vector<Contact> contacts;  // by mass index, from the parts' contacts across masses
};

struct LevelMassing {
  size_t index = 0;  // into Params::dec.levels
  double threshold = 0;
  std::vector<PartMassing> parts;
  std::vector<MassMassing> masses;
};

struct MassingFeatures {
  bool valid = false;
  double level = 0;  // the level they describe
  int tiers = 0, setbacks = 0, wings = 0, annexes = 0, rooftop_units = 0, courtyards = 0;
  bool tower_on_podium = false;
  int edges = 0, cycles = 0;  // contact graph: edges, independent cycles (E - V + components)
};

struct BuildingMassing {
  std::vector<LevelMassing> levels;  // the written levels
  MassingFeatures features;
  mc::io::MultiPolygon2 footprint;  // union of the analysis level's part footprints
};

// One level: `meshes[j]` is part j (Polygon::neighbour set, level_part_meshes), `parts[j]` its result.
LevelMassing analyse_level(const std::vector<PolygonMesh>& meshes, const std::vector<PartResult>& parts,
                           size_t index, double threshold, const MassingParams& p);

// The building features and footprint from the written level nearest (in log) to p.level.
void finish_massing(BuildingMassing& m, const MassingParams& p);

// The footprints' coordinates from the building's metric working frame to the file's (for the
// GeoPackage); every area and length stays as measured, in metres.
void to_file(BuildingMassing& m, const WorkingFrame& frame);

// The morphcut_* part attributes of part j (ids of neighbours: <building>-mc<index>-<k>).
void add_part_attributes(nlohmann::json& attributes, const LevelMassing& level, size_t j,
                         const std::string& building);
// The morphcut_* building attributes (nothing when the features are not valid).
void add_building_attributes(nlohmann::json& attributes, const BuildingMassing& m);
// The building attribute names above (to strip from a re-run's input).
const std::vector<std::string>& building_attribute_names();

// CSV columns (appended to the planners' CSV) and their values for one building.
const std::vector<std::string>& massing_columns();

// Cache round trip.
nlohmann::json massing_to_json(const BuildingMassing& m);
void massing_from_json(const nlohmann::json& j, BuildingMassing& m);

// One line of OUT.morphcut.graph.jsonl.
nlohmann::json graph_json(const std::string& building, const std::string& status, const BuildingMassing& m);

}  // namespace mc::massing
