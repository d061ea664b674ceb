// morphcut-city html: argument handling only; the page is report/html_report.cpp.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/errors.hpp"
#include "tools/cli/cli.hpp"
#include "report/html_report.hpp"
#include "tools/cli/subcommands.hpp"

namespace mc::cli {

using namespace mc::report;

namespace {

const char* kFooter =
    R"(REPORT is a morphcut-city run report (<stem>.morphcut.report.json) or a merge-reports result
(the tiles' city outputs are found through each tile's report). CITY files default to the outputs
the report names (outputs.cityjson and, when written per level, outputs.levels[].cityjson);
give them when the outputs were moved, or pass `-` as REPORT to make a page from city files alone.
The page is one file that works offline: data, script and three.js inline, no network request.
3D geometry is embedded for at most --max-3d buildings and --max-3d-mb megabytes (all buildings when
they fit; otherwise failed and partial ones first, then the slowest and the least convex alternately).

Exit codes: 0 written, 2 usage error, unreadable report or unwritable page.
)";

}  // namespace

int html_main(int argc, char** argv) {
  CLI::App app{"morphcut-city html - a self-contained HTML page of a run (summary, plots, plan, 3D parts)",
               "morphcut-city html"};
  std::string report, out;
  std::vector<std::string> cities;
  HtmlReportOptions opt;
  double max_3d_mb = static_cast<double>(opt.max_3d_bytes) / 1e6;
  bool quiet = false;
  app.add_option("REPORT", report, "run report or merged report JSON; - = none (CITY files only)")
      ->required();
  app.add_option("CITY", cities, "CityJSON / CityJSONSeq outputs (default: those the report names)");
  app.add_option("-o,--output", out, "page to write (default: REPORT with .report.json -> .html)");
  app.add_option("--max-3d", opt.max_3d_buildings, "buildings whose 3D geometry is embedded at most")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--max-3d-mb", max_3d_mb, "megabytes of 3D geometry (JSON) embedded at most")
      ->check(CLI::PositiveNumber);
  app.add_option("--max-footprints", opt.max_footprints,
                 "buildings drawn as footprints in the plan at most (others: dots)")
      ->check(CLI::NonNegativeNumber);
  app.add_flag("--quiet,-q", quiet, "print nothing but errors");
  app.footer(kFooter);
  if (const auto code = parse_or_exit(app, argc, argv)) return *code;
  opt.max_3d_bytes = static_cast<size_t>(max_3d_mb * 1e6);
  if (report == "-") report.clear();
  if (report.empty() && cities.empty()) {
    std::fprintf(stderr, "morphcut-city html: give a report or CITY files\n");
    return kExitUsage;
  }
  if (out.empty()) out = !report.empty() ? html_path_for_report(report) : cities[0] + ".html";
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const HtmlReportResult r = write_html_report(report, cities, out, opt);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!quiet) {
      for (const auto& w : r.warnings) std::fprintf(stderr, "morphcut-city html: warning: %s\n", w.c_str());
      std::fprintf(
          stderr,
          "morphcut-city html: %zu buildings (3D for %zu) from %zu city files, %.2f MB in %.2f s -> %s\n",
          r.buildings, r.with_3d, r.city_files.size(), static_cast<double>(r.bytes) / 1e6, s, r.path.c_str());
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "morphcut-city html: %s\n", e.what());
    return kExitUsage;
  }
}

}  // namespace mc::cli
