// Run outputs of the massing analytics (docs/massing.md), both atomic like every output:
//   - OUT.morphcut.graph.jsonl: one building per line (graph_json in massing/massing.hpp): per
//     written level the part graph, nodes with their attributes and role, edges with contact kind
//     and shared area; buildings without parts have no levels;
//   - OUT.morphcut.gpkg: layers `buildings` (footprint union at the analysis level, every column
//     of the planners' CSV) and `parts` (every written part's footprint).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "io/gpkg_writer.hpp"
#include "report/outcome.hpp"

namespace mc::io {
class AtomicFile;
class GpkgWriter;
}  // namespace mc::io

namespace mc::report {

class GraphWriter {
 public:
  explicit GraphWriter(const std::string& path);  // throws mc::io::WriteError
  ~GraphWriter();
  void add(const BuildingOutcome& b);
  void commit();

 private:
  std::string path_;
  std::unique_ptr<mc::io::AtomicFile> file_;
};

class MassingGpkgWriter {
 public:
  // `crs` from the input header; `thresholds`: the written levels (the CSV's parts_<t> columns).
  MassingGpkgWriter(const std::string& path, const std::string& crs, std::vector<double> thresholds,
                    int coordinate_decimals = 3);
  ~MassingGpkgWriter();
  void add(const BuildingOutcome& b);
  void commit();

 private:
  std::vector<double> thresholds_;
  int decimals_ = 3;
  std::vector<mc::io::GpkgColumn> columns_;
  std::unique_ptr<mc::io::GpkgWriter> gpkg_;
};

// OUT.city.json -> OUT.morphcut.graph.jsonl / OUT.morphcut.gpkg, from the outputs' stem (the
// stem the CLI uses for the report: OUT without .city.json/.city.jsonl/.json/.jsonl).
std::string graph_path_for_stem(const std::string& stem);
std::string gpkg_path_for_stem(const std::string& stem);

}  // namespace mc::report
