#include "pipeline/run_outputs.hpp"

#include "output/level_views.hpp"
#include "pipeline/run.hpp"

namespace mc::pipeline {

using namespace mc::output;
using namespace mc::report;

namespace {

std::vector<double> written_levels(const Params& params, const RunConfig& rc) {
  std::vector<double> levels;
  for (size_t i = 0; i < params.dec.levels.size(); ++i)
    if (writes_level(rc, i)) levels.push_back(params.dec.levels[i]);
  return levels;
}

}  // namespace

RunOutputs::RunOutputs(const RunOptions& opt, const mc::io::Header& header, const Params& params,
                       const RunConfig& rc)
    : header_(header), levels_(written_levels(params, rc)), crs_(header.crs), city_(opt.output, header) {
  for (double t : levels_)
    level_cities_.push_back(
        std::make_unique<mc::io::CityJsonWriter>(level_output_path(opt.output, t), header));
  if (!opt.report.empty()) report_ = std::make_unique<ReportWriter>(opt.report);
  // Centroids to 0.1 mm: 3 decimals of metres, 9 of degrees.
  const int decimals = header.coords.geographic() ? 9 : 3;
  if (!opt.summary.empty()) summary_ = std::make_unique<SummaryWriter>(opt.summary, levels_, decimals);
  if (!opt.graph.empty()) graph_ = std::make_unique<GraphWriter>(opt.graph);
  if (!opt.gpkg.empty()) gpkg_ = std::make_unique<MassingGpkgWriter>(opt.gpkg, header.crs, levels_, decimals);
}

void RunOutputs::write_cities(BuildingOutcome& b) {
  if (b.is_building) {
    city_.write(annotated_view(b.feature));
    for (size_t l = 0; l < level_cities_.size(); ++l)
      level_cities_[l]->write(level_view(b.feature, header_, levels_[l], b.lod));
  } else {
    city_.write(b.feature);
    for (auto& lw : level_cities_) lw->write(b.feature);
  }
  b.feature = mc::io::Feature{};  // release the geometry before the reports
}

void RunOutputs::write_rows(BuildingOutcome& b) {
  if (b.measures.centroid && crs_.valid())
    b.measures.lonlat =
        crs_.to_lonlat(b.measures.centroid->x, b.measures.centroid->y, b.measures.centroid->z);
  if (report_) report_->add(b);
  if (summary_) summary_->add(b);
  if (graph_) graph_->add(b);
  if (gpkg_) gpkg_->add(b);
}

void RunOutputs::commit_files() {
  city_.close();
  for (auto& lw : level_cities_) lw->close();
  if (summary_) summary_->commit();
  if (graph_) graph_->commit();
  if (gpkg_) gpkg_->commit();
}

}  // namespace mc::pipeline
