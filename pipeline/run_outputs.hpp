// Every file a run writes (docs/output-format.md), opened before any work so that a bad path fails
// first: the annotated input and one city per written level (output/level_views.hpp), the run
// report, the planners' CSV, the part graphs and the GeoPackage. All atomic: nothing appears
// unless commit() is reached.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/run_config.hpp"
#include "core/params.hpp"
#include "io/cityjson_writer.hpp"
#include "io/crs.hpp"
#include "report/graph_export.hpp"
#include "report/outcome.hpp"
#include "report/report.hpp"
#include "report/summary_csv.hpp"

namespace mc::pipeline {

struct RunOptions;

class RunOutputs {
 public:
  // Throws mc::io::WriteError when a file cannot be created.
  RunOutputs(const RunOptions& opt, const mc::io::Header& header, const Params& params, const RunConfig& rc);

  // A finished feature into every city file (its geometry is released afterwards).
  void write_cities(mc::report::BuildingOutcome& b);
  // A building's rows: the report, the CSV, the graph and the GeoPackage (lon/lat of its centroid
  // added first when the CRS allows).
  void write_rows(mc::report::BuildingOutcome& b);
  // Closes the city files, the CSV, the graphs and the GeoPackage (the report is committed by the
  // caller with the run's figures: has_report(), commit_report()).
  void commit_files();
  bool has_report() const { return report_ != nullptr; }
  void commit_report(const nlohmann::ordered_json& run) { report_->commit(run); }

  const std::vector<double>& levels() const { return levels_; }  // the thresholds written
  const mc::io::CrsTransformer& crs() const { return crs_; }
  size_t dropped_extras() const { return city_.dropped_extras(); }

 private:
  const mc::io::Header& header_;
  std::vector<double> levels_;
  mc::io::CrsTransformer crs_;
  mc::io::CityJsonWriter city_;
  std::vector<std::unique_ptr<mc::io::CityJsonWriter>> level_cities_;
  std::unique_ptr<mc::report::ReportWriter> report_;
  std::unique_ptr<mc::report::SummaryWriter> summary_;
  std::unique_ptr<mc::report::GraphWriter> graph_;  // massing analytics (docs/massing.md)
  std::unique_ptr<mc::report::MassingGpkgWriter> gpkg_;
};

}  // namespace mc::pipeline
