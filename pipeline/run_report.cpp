#include "pipeline/run_report.hpp"

#include <cmath>
#include <filesystem>

#include "config/config.hpp"
#include "output/level_views.hpp"
#include "pipeline/job_cpu.hpp"

namespace mc::pipeline {

using ojson = nlohmann::ordered_json;

namespace {

// The report's account of the coordinates: the input's CRS and units, the metric frame the
// buildings were decomposed in, and what the outputs are written in.
ojson coordinates_json(const mc::io::Header& input, const mc::io::Header& output,
                       const mc::output::OutputGrid& grid) {
  const CoordinateSystem& cs = output.coords;
  std::string frame = "the file's coordinates (metres)";
  if (cs.projected_per_building())
    frame =
        "a transverse Mercator projection per building, central meridian and origin at the building's "
        "centre, scale 1 (scale error below 1.3e-8 within 1 km), heights kept";
  else if (!cs.metric()) frame = "the file's coordinates scaled to metres";
  auto vec = [](const Vec3& v) { return ojson::array({v.x, v.y, v.z}); };
  return {{"input_crs", input.crs.empty() ? ojson(nullptr) : ojson(input.crs)},
          {"input_units", input.coords.describe()},
          {"output_crs", output.crs.empty() ? ojson(nullptr) : ojson(output.crs)},
          {"output_units", cs.describe()},
          {"working_frame", frame},
          {"measures_in", "metres (lengths, heights), square metres (areas), cubic metres (volumes)"},
          {"output_grid", grid.present ? vec(grid.scale) : ojson(nullptr)},
          {"output_grid_refined_from", grid.refined ? vec(grid.input_scale) : ojson(nullptr)}};
}

}  // namespace

ojson run_report(const RunOptions& opt, const Params& params, const RunConfig& rc, const RunResult& res,
                 RunInput& in, const RunOutputs& outputs, const std::string& cache_dir) {
  std::string sha;
  if (in.sha256.valid()) sha = in.sha256.get();
  std::error_code ec;
  const auto bytes = opt.input == "-" ? 0 : std::filesystem::file_size(opt.input, ec);
  ojson counts = ojson::object();
  for (const char* s : mc::report::kStatuses) counts[s] = res.counts.at(s);
  ojson level_outputs = ojson::array();
  for (double t : outputs.levels())
    level_outputs.push_back({{"threshold", t}, {"cityjson", mc::output::level_output_path(opt.output, t)}});
  const mc::io::Header& header = in.header;
  const mc::io::CrsTransformer& crs = outputs.crs();
  ojson run = {{"tool", "morphcut-city"},
               {"version", MC_VERSION},
               {"input",
                {{"path", opt.input},
                 {"format", in.source->format()},
                 {"version", header.version},
                 {"crs", header.crs},
                 {"bytes", ec ? ojson(nullptr) : ojson(bytes)},
                 {"sha256", sha.empty() ? ojson(nullptr) : ojson(sha)}}},
               {"outputs",
                {{"cityjson", opt.output},
                 {"levels", level_outputs},
                 {"report", opt.report},
                 {"summary", opt.summary},
                 {"graph", opt.graph},
                 {"gpkg", opt.gpkg}}},
               {"config_file", opt.config_file.empty() ? ojson(nullptr) : ojson(opt.config_file)},
               {"config", ojson::parse(effective_config_json(params, rc).dump())},
               {"threads", res.threads},
               {"in_flight", res.in_flight},
               {"wall_seconds", res.wall_seconds},
               {"buildings_per_second", res.wall_seconds > 0 ? res.buildings / res.wall_seconds : 0.0},
               {"cpu_seconds", std::round(process_cpu_seconds() * 1e3) / 1e3},
               {"peak_rss_mb", res.peak_rss_mb},
               {"features", res.features},
               {"building_count", res.buildings},
               {"counts", counts},
               {"cache", !cache_dir.empty() ? ojson{{"dir", cache_dir},
                                                    {"hits", res.cache.hits},
                                                    {"misses", res.cache.misses},
                                                    {"stored", res.cache.stored},
                                                    {"not_stored", res.cache.not_stored},
                                                    {"corrupt", res.cache.corrupt},
                                                    {"store_errors", res.cache.store_errors}}
                                            : ojson(nullptr)},
               {"crs_for_wgs84", crs.valid() ? ojson(header.crs) : ojson(nullptr)},
               {"coordinates", coordinates_json(in.source->header(), header, in.grid)},
               {"reader_problems", res.reader_problems},
               {"dropped_feature_extras", outputs.dropped_extras()}};
  if (!crs.valid() && !header.crs.empty()) run["crs_error"] = crs.error();
  return run;
}

}  // namespace mc::pipeline
