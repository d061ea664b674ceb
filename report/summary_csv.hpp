// The planners' summary (docs/output-format.md, the files table): one RFC 4180 row per building, streamed to
// an atomic file. Columns:
//   id, status, reason, lod, parts_<l> for each written level l,
//   height            max z - min z of the input geometry,
//   footprint_area    projected area of the GroundSurface faces, or of the 2D convex hull of
//   footprint_method  all vertices when there is no GroundSurface ("ground" / "hull"),
//   volume            of the reconstructed solid (all interior components),
//   convexity         whole building: volume / volume of its convex hull,
//   mean_part_convexity, largest_part_share, max_degree, end_parts
//                     of the finest written level (end parts: exactly one neighbour),
//   centroid_x/y/z    volume centroid of the solid in the source CRS (input bounding-box centre
//   centroid_method   when there is no solid: "solid" / "bbox"),
//   lon, lat          WGS84 degrees of the centroid (empty without a usable CRS),
//   morphcut_massing_level, morphcut_tiers, _setbacks, _wings, _annexes, _rooftop_units,
//   _courtyards, _tower_on_podium, _graph_edges, _graph_cycles   massing features (docs/massing.md).
// Unknown values are empty fields (read as NULL by QGIS).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "report/outcome.hpp"

namespace mc::io {
class AtomicFile;
class CsvWriter;
}  // namespace mc::io

namespace mc::report {

// The header row for these written level thresholds.
std::vector<std::string> summary_columns(const std::vector<double>& level_thresholds);

// One cell of a row: its CSV text and typed value (the GeoPackage's buildings layer has the same columns).
struct SummaryCell {
  enum Kind { Empty, Text, Integer, Real } kind = Empty;
  std::string text;
  long long integer = 0;
  double real = 0;
  int precision = 0;
};
// The row of one building, in the order of summary_columns.
// `coordinate_decimals`: of the centroid's x and y (3 for metres, 9 for degrees: 0.1 mm either way).
std::vector<SummaryCell> summary_row(const BuildingOutcome& b, const std::vector<double>& level_thresholds,
                                     int coordinate_decimals = 3);

class SummaryWriter {
 public:
  // Throws mc::io::WriteError when the file cannot be created.
  SummaryWriter(const std::string& path, std::vector<double> level_thresholds, int coordinate_decimals = 3);
  ~SummaryWriter();
  void add(const BuildingOutcome& b);
  void commit();

 private:
  std::string path_;
  std::vector<double> thresholds_;
  int decimals_ = 3;
  std::unique_ptr<mc::io::AtomicFile> file_;
  std::unique_ptr<mc::io::CsvWriter> csv_;
};

}  // namespace mc::report
