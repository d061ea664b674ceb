// morphcut-city merge-reports: argument handling only; the merge is report/merge_reports.cpp.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "io/errors.hpp"
#include "report/merge_reports.hpp"
#include "tools/cli/cli.hpp"
#include "tools/cli/subcommands.hpp"

namespace mc::cli {

using namespace mc::report;

namespace {

const char* kFooter =
    R"(Tiles are given either as report paths (the CSV beside each report, x.morphcut.report.json ->
x.morphcut.csv, is merged too), or as the tile list given to the array (one input path per line;
blank lines and #-comments ignored) with the directory the tiles were written to: the report of
tile `a/b/5910.city.json` is then DIR/5910.morphcut.report.json.

Exit codes:
  0  every tile merged
  1  some tile's report (or CSV) is missing or unreadable: the merged outputs are written and list
     it under missing_tiles (a failed array task)
  2  usage error, or the merged outputs cannot be written
Tiles made with another tool version or config are merged with a warning recorded in the report.
)";

std::vector<std::string> read_tile_list(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the tile list " + path);
  std::vector<std::string> tiles;
  std::string line;
  while (std::getline(in, line)) {
    const auto b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos || line[b] == '#') continue;
    const auto e = line.find_last_not_of(" \t\r");
    tiles.push_back(line.substr(b, e - b + 1));
  }
  return tiles;
}

}  // namespace

int merge_reports_main(int argc, char** argv) {
  CLI::App app{"morphcut-city merge-reports - merge per-tile run reports and CSVs into one",
               "morphcut-city merge-reports"};
  std::vector<std::string> reports;
  std::string tile_list, dir, out, csv_out;
  bool no_csv = false;
  app.add_option("REPORTS", reports, "per-tile run reports (<stem>.morphcut.report.json)");
  app.add_option("--tiles", tile_list, "tile list (one input path per line), with --dir");
  app.add_option("--dir", dir, "directory holding the tiles' outputs (with --tiles)");
  app.add_option("-o,--output", out, "merged report JSON")->required();
  app.add_option("--csv", csv_out, "merged CSV (default: the output with .report.json -> .csv)");
  app.add_flag("--no-csv", no_csv, "do not merge the CSVs");
  app.footer(kFooter);
  if (const auto code = parse_or_exit(app, argc, argv)) return *code;
  try {
    if (!tile_list.empty() == !reports.empty())
      throw CLI::ValidationError("give either REPORTS or --tiles LIST --dir DIR");
    if (!tile_list.empty() && dir.empty()) throw CLI::ValidationError("--tiles needs --dir");
    MergeOptions opt;
    opt.report_out = out;
    if (!no_csv) {
      opt.csv_out = !csv_out.empty() ? csv_out : csv_beside_report(out);
      if (opt.csv_out.empty()) opt.csv_out = out + ".csv";
    }
    if (!tile_list.empty()) {
      for (const auto& input : read_tile_list(tile_list)) {
        const std::string stem = input_stem(input);
        const std::string report = dir + "/" + stem + ".morphcut.report.json";
        opt.tiles.push_back({stem, report, csv_beside_report(report)});
      }
    } else {
      for (const auto& r : reports) opt.tiles.push_back({tile_name_of_report(r), r, csv_beside_report(r)});
    }
    if (opt.tiles.empty()) throw CLI::ValidationError("no tiles to merge");

    const MergeResult r = merge_reports(opt);
    for (const auto& w : r.warnings) std::fprintf(stderr, "merge-reports: warning: %s\n", w.c_str());
    for (const auto& m : r.missing) std::fprintf(stderr, "merge-reports: missing tile %s\n", m.c_str());
    std::fprintf(
        stderr,
        "merge-reports: %zu of %zu tiles, %zu buildings (%zu ok, %zu partial, %zu failed, %zu skipped), "
        "%zu duplicate ids -> %s%s%s\n",
        r.merged, r.tiles, r.buildings, r.counts.at("ok"), r.counts.at("partial"), r.counts.at("failed"),
        r.counts.at("skipped"), r.duplicate_ids, out.c_str(), opt.csv_out.empty() ? "" : ", ",
        opt.csv_out.c_str());
    return r.exit_code();
  } catch (const CLI::Error& e) {
    std::fprintf(stderr, "merge-reports: %s\n", e.what());
  } catch (const mc::io::WriteError& e) {
    std::fprintf(stderr, "merge-reports: cannot write: %s\n", e.what());
  } catch (const std::exception& e) { std::fprintf(stderr, "merge-reports: error: %s\n", e.what()); }
  return kExitUsage;
}

}  // namespace mc::cli
