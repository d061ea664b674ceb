// Merges per-tile run reports and summary CSVs into one city report and one CSV (the aggregation
// step after a Slurm job array, or after tools/slurm/run-local.sh; usable on its own).
//
// Merged report (JSON, written atomically):
//   tool, version
//   tiles          one summary per tile, in argument order: tile name, report path and SHA-256,
//                  input path and SHA-256, tool version, config hash, building_count, counts,
//                  wall_seconds, cache counts, CSV path and rows
//   missing_tiles  tiles whose report is absent or unreadable (a failed array task), with why
//   totals         tiles, merged, missing, building_count, counts by status, wall_seconds (sum),
//                  cache hits/misses (sum), duplicate ids
//   duplicates     building ids found in more than one tile (a building on a tile border), sorted,
//                  with the tiles holding them; every copy is kept in `buildings`
//   warnings       tiles produced by another tool version or another effective config (worker
//                  threads, in-flight bound and log level excepted), CSV column or row mismatches
//   buildings      every building entry of every merged tile, in tile order, with "tile" first
// Merged CSV: one header, "tile" as the first column, then the union of the tiles' columns in
// first-seen order (tiles with other columns, e.g. other output levels, get empty fields and a
// warning), then every row of every tile in tile order.
// Memory: one tile's report and CSV at a time (entries and rows are spooled to scratch files) plus
// the set of building ids needed to find duplicates.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace mc::report {

struct TileReport {
  std::string name;    // the tile's name in the merged outputs (the input stem)
  std::string report;  // its run report
  std::string csv;     // its summary CSV; empty = none expected
};

struct MergeOptions {
  std::vector<TileReport> tiles;
  std::string report_out;  // merged report
  std::string csv_out;     // merged CSV; empty = not written
};

struct MergeResult {
  size_t tiles = 0, merged = 0;
  std::vector<std::string> missing;  // "tile: why"
  std::vector<std::string> warnings;
  size_t buildings = 0, csv_rows = 0;
  std::map<std::string, size_t> counts;  // by status
  size_t duplicate_ids = 0;
  bool csv_incomplete = false;  // a tile's CSV was expected but missing or unreadable
  // 0 every tile merged; 1 some tile missing or incomplete (the merged outputs list what is there).
  int exit_code() const { return missing.empty() && !csv_incomplete ? 0 : 1; }
};

// "out/5910.morphcut.report.json" -> "5910"; other names lose ".report.json" or ".json".
std::string tile_name_of_report(const std::string& report_path);
// The CSV morphcut-city writes beside a report by default: x.morphcut.report.json -> x.morphcut.csv
// (empty when the report does not follow that naming).
std::string csv_beside_report(const std::string& report_path);
// The stem morphcut-city names outputs after: "tiles/5910.city.json" -> "5910".
std::string input_stem(const std::string& input_path);

// Throws mc::io::WriteError when an output cannot be written (nothing is then left behind).
MergeResult merge_reports(const MergeOptions& opt);

}  // namespace mc::report
