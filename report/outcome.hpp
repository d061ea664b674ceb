// What one building's job hands to the writer and the reports.
#pragma once
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/vec3.hpp"
#include "io/cityjson_types.hpp"
#include "massing/massing.hpp"

namespace mc::report {

// Statuses, in report order.
inline constexpr const char* kStatuses[] = {"ok", "partial", "failed", "skipped"};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One written LoD level of one building.
struct LevelOutcome {
  size_t index = 0;      // into Params::dec.levels (the `mc<index>` of the part ids)
  double threshold = 0;  // the LoD threshold l
  size_t parts = 0;
  double convexity = kNaN;  // volume-weighted mean of V/V_CH
  double mean_convexity = kNaN, min_convexity = kNaN;
  double largest_share = kNaN;  // volume of the largest part / building volume
  double cost = kNaN, g = kNaN, h = kNaN;
  int remaining_concave = 0;
  int64_t nodes_expanded = 0;
  double seconds = 0;
  bool truncated = false;
  // Where the parts come from when this level was not reached before the deadline:
  // "" (searched), "previous level" or "singleton".
  std::string fallback;
  int max_degree = 0;  // part adjacency graph
  int end_parts = 0;   // parts with exactly one neighbour
  // What the level needed beyond per-part repairs for every part to pass the checks on the
  // output grid: "" (nothing), "cluster N" (vertices within N grid steps made one), or
  // "non-conforming" (each part's mesh on its own; docs/output-format.md §Validity).
  std::string grid_repair;
};

struct Timings {
  double read = 0, extract = 0, preprocess = 0, decompose = 0, encode = 0, job = 0, write = 0;
  double massing = 0;  // massing analytics (massing/massing.hpp), a part of encode
  double check = 0;    // checking (and repairing) the parts on the output grid, a part of encode
  double cpu = 0;      // CPU seconds of the job over every thread that worked for it (pipeline/job_cpu.hpp)
};

struct Sizes {
  size_t input_faces = 0, input_vertices = 0, regions = 0, planes = 0, cells = 0, inside_cells = 0;
  size_t components = 0, dropped_components = 0;
  bool cell_closed = false, cell_manifold = false;  // the singleton cell (preprocessing)
  int concave_edges = 0;
  size_t parts_written = 0, output_vertices_added = 0, dropped_faces = 0;
  size_t parts_repaired = 0, split_faces = 0;  // parts that needed a repair on the output grid
};

// Whole-building measures for the planners' CSV.
struct Measures {
  std::optional<double> height, footprint_area, volume, convexity;
  std::string footprint_method;                     // "ground" or "hull" (see measures.hpp)
  std::optional<Vec3> centroid;                     // source CRS
  std::string centroid_method;                      // "solid" (volume centroid) or "bbox" (input box centre)
  std::optional<std::pair<double, double>> lonlat;  // WGS84, filled by the run (needs the CRS)
};

// The singleton cell's volume check (docs/algorithm.md §6.5): the cell against an independent
// estimate of the volume the input encloses. `flagged`: the disagreement exceeds
// preprocess.volume_check after a second labelling; the status stays as it is, the Building gets
// `morphcut_volume_check` (docs/output-format.md).
struct VolumeCheckOutcome {
  double estimate = kNaN, cell = kNaN, ratio = kNaN;
  std::string method;  // "signed volume" or "vertical columns"; empty: no estimate
  std::string oracle;  // "parity" or "vertical": the labelling kept
  bool open_input = false, relabelled = false, flagged = false;
  // The labelling's fast path for valid solids (docs/algorithm.md §6.6), or why not.
  bool fast_path = false;
  std::string fast_path_reason;
};

struct BuildingOutcome {
  mc::io::Feature feature;   // the feature to write: input kept, parts and attributes added
  bool is_building = false;  // false: passed through untouched, not in the reports
  std::string id;
  std::string status;  // ok, partial, failed, skipped
  std::string reason;  // empty when ok
  std::string lod;     // the input LoD decomposed
  Timings time;
  Sizes size;
  double hausdorff = kNaN;
  VolumeCheckOutcome volume_check;
  std::vector<LevelOutcome> levels;  // the written levels, in level order
  Measures measures;
  mc::massing::BuildingMassing massing;  // part roles, contacts and building features (massing/massing.hpp)
  std::vector<std::string> problems;     // read/extraction/preprocessing problems (capped)
  size_t sequence = 0;                   // input order (set by the run)
};

}  // namespace mc::report
