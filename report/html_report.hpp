// The run as one self-contained, offline HTML page: run summary, plots, a plan view of
// the footprints and an interactive three.js view of any embedded building's parts per level,
// with the input as a ghost. Data, page script and three.js are inline; the page makes no request
// (its Content-Security-Policy forbids any).
//
// Sources: the run report (or a merge-reports result) for the facts and per-building results, and
// the CityJSON/CityJSONSeq outputs for geometry. Parts are the BuildingParts carrying
// `morphcut_level`, collected by level from every city file given (the main output or one file
// per level); a building's input ghost is its own non-morphcut geometry at the highest LoD, from
// the first file that has it. Coordinates are real-world (the file's transform applied), then
// centred on the city's minimum x/y so that the browser's float32 keeps millimetres.
//
// Size bound: 3D geometry is embedded for at most `max_3d_buildings` buildings and
// `max_3d_bytes` of JSON (every building of the 3D BAG demo tile: 432, 2.9 MB); for a larger city
// the failed and partial buildings first, then the slowest and the least convex at the finest
// level alternately. Every building keeps its table row, plot points and plan footprint (a dot
// beyond `max_footprints`).
// The page is deterministic: the same inputs give the same bytes (no time stamps).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mc::report {

struct HtmlReportOptions {
  size_t max_3d_buildings = 500;
  size_t max_3d_bytes = 4'000'000;
  size_t max_footprints = 20000;
};

struct HtmlReportResult {
  std::string path;
  uint64_t bytes = 0;
  size_t buildings = 0;                 // rows on the page
  size_t with_3d = 0;                   // buildings whose geometry is embedded
  size_t footprints = 0;                // buildings drawn as footprints in the plan view
  std::vector<std::string> city_files;  // the files read
  std::vector<std::string> warnings;    // city files missing or unreadable, buildings without geometry, ...
};

// `report_json_path`: a morphcut-city run report or a merge-reports result; empty = none (the
// page is then made from the morphcut_* attributes of the city files alone).
// `city_paths`: CityJSON / CityJSONSeq outputs; empty = the files the report names
// (city_files_of_report). Writes `out_html_path` atomically.
// Throws mc::io::ReadError when the report cannot be read or no data is found at all,
// mc::io::WriteError when the page cannot be written.
HtmlReportResult write_html_report(const std::string& report_json_path,
                                   const std::vector<std::string>& city_paths,
                                   const std::string& out_html_path, const HtmlReportOptions& opt = {});

// The city outputs a report names: outputs.cityjson and outputs.levels[].cityjson; for a merged
// report those of every tile's report. A relative path that does not exist from the current
// directory is looked up beside the report. Unreadable reports give no files.
std::vector<std::string> city_files_of_report(const std::string& report_json_path);

// The page's default name beside a report: x.report.json -> x.html (so x.morphcut.report.json ->
// x.morphcut.html); any other name gets ".html" appended.
std::string html_path_for_report(const std::string& report_path);

}  // namespace mc::report
