// morphcut-city: decompose every building of a CityJSON city into convex parts (MorphCut).
// The CLI only parses arguments, resolves defaults and maps outcomes to exit codes; the work is
// pipeline::run_city (pipeline/run.hpp).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

#include "config/config.hpp"
#include "io/errors.hpp"
#include "tools/cli/cli.hpp"
#include "report/html_report.hpp"
#include "report/graph_export.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/run.hpp"
#include "tools/cli/subcommands.hpp"

namespace {

// "tiles/5910.city.json" -> "5910"; "-" -> "stdin".
std::string stem_of(const std::string& input) {
  if (input == "-") return "stdin";
  std::string name = std::filesystem::path(input).filename().string();
  for (const char* ext :
       {".city.jsonl", ".city.json", ".jsonl", ".json", ".gml.gz", ".xml.gz", ".gml", ".xml"})
    if (name.ends_with(ext) && name.size() > std::string(ext).size())
      return name.substr(0, name.size() - std::string(ext).size());
  return name;
}

// The output path without its extension and a trailing ".morphcut" (x.morphcut.city.json -> x).
std::string output_stem(const std::string& output) {
  const std::filesystem::path p(output);
  std::string name = stem_of(output);
  if (name.ends_with(".morphcut") && name.size() > 9) name.resize(name.size() - 9);
  return (p.parent_path() / name).string();
}

struct CliArgs;
std::string output_stem_of(const CliArgs& a);

const char* kFooter =
    R"(Outputs (written to the current directory, REPORT and SUMMARY beside OUTPUT when -o is given):
  OUTPUT   <stem>.morphcut.city.json (<stem>.morphcut.city.jsonl for CityJSONSeq input):
           the input unchanged (CityGML input: its buildings converted to CityJSON 2.0, see the
           README) plus, per building and output LoD level, convex BuildingParts
           <building id>-mc<level index>-<part index> with closed Solids, and the attributes
           morphcut_status, morphcut_reason, morphcut_parts, morphcut_levels, morphcut_hausdorff,
           morphcut_cell_volume (m³, the singleton cell: every level's parts add up to it;
           `morphcut-city validate OUTPUT` checks that and every part, see its --help)
  REPORT   <stem>.morphcut.report.json: version, effective config, input hash, timings, sizes
           and per-level results for every building
  SUMMARY  <stem>.morphcut.csv: one RFC 4180 row per building for planners (parts per level,
           height, footprint, volume, convexities, part-graph statistics, centroid, lon/lat)
  GRAPH    <stem>.morphcut.graph.jsonl: per building and level the part graph (nodes with role
           and geometry, edges with contact kind and shared area; docs/massing.md)
  GPKG     <stem>.morphcut.gpkg: GeoPackage with layers `buildings` (footprint, every SUMMARY
           column) and `parts` (each part's footprint, level, role, z range, volume, convexity)
  HTML     <stem>.morphcut.html beside the report (REPORT with .report.json -> .html): one
           self-contained page that works offline (run summary, plots, plan of the footprints, 3D
           view of each building's parts per level); `morphcut-city html REPORT.json` remakes it
  All outputs are atomic: they appear complete or not at all.
  CRASHES  OUTPUT.crashed: a building that crashes the process (a signal such as SIGSEGV or
           SIGABRT) is recorded there; the next run writes it through as failed with that
           reason, so the city completes. Delete the file to try those buildings again.

Building status (attribute morphcut_status, with morphcut_reason when not ok):
  ok       every level decomposed
  partial  the deadline was reached (the best result so far is written), or a level's parts
           were not valid solids (a valid coarser or finer level is written in its place)
  failed   an error: the building is written through unchanged
  skipped  no surface geometry at the requested LoD, or more faces than max_faces (too large)
Running on a morphcut output replaces the parts of the earlier run.

Exit codes:
  0    every building ok (or skipped)
  1    some buildings failed or are partial (all are still in the output)
  2    usage, configuration, read or write error (no output written)
  130  interrupted by SIGINT, 143 by SIGTERM (no output written; a second signal exits at once)
)";

// What the command line says, before defaults are resolved.
struct CliArgs {
  std::string input, config_path, output, report, summary, lod, cache_dir, html, graph, gpkg, output_crs;
  bool no_graph = false, no_gpkg = false, quiet = false, no_report = false, no_summary = false,
       no_html = false;
  bool print_config = false, print_reference = false, no_fast_path = false;
  int threads = -1;
  double timeout = -1;
};

// Declares every option; returns the input's (required unless --print-config, checked after parsing).
CLI::Option* declare_options(CLI::App& app, CliArgs& a) {
  CLI::Option* input_opt =
      app.add_option("INPUT", a.input,
                     "input city: .city.json (CityJSON 1.0/1.1/2.0), .city.jsonl (CityJSONSeq), "
                     ".gml/.xml[.gz] (CityGML 1.0/2.0/3.0 buildings), or - for CityJSONSeq on stdin");
  app.add_option("--config,-c", a.config_path,
                 "YAML configuration (see config/lod.yaml; unknown keys are rejected)")
      ->check(CLI::ExistingFile);
  app.add_option("-o,--output", a.output,
                 "output CityJSON; .jsonl writes CityJSONSeq (default: <stem>.morphcut.city.json[l])");
  app.add_option("--threads,-j", a.threads, "worker threads; 0 = all cores (default: config `threads`)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--timeout", a.timeout,
                 "per-building deadline in seconds; 0 = none (default: config `timeout_s`)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--lod", a.lod, "input LoD to decompose, e.g. 2.2, or `highest` (default: config `lod`)");
  app.add_option("--report", a.report, "run report JSON (default: <stem>.morphcut.report.json)");
  app.add_option("--summary", a.summary, "summary CSV (default: <stem>.morphcut.csv)");
  app.add_option(
      "--cache", a.cache_dir,
      "per-building result cache directory: unchanged buildings (same geometry, config and version) "
      "reuse their earlier parts; safe to share between concurrent runs");
  app.add_option("--output-crs", a.output_crs,
                 "write every output in this CRS (e.g. EPSG:32654), reprojecting the input as it is read "
                 "(horizontal coordinates; heights are kept). Default: the input's CRS, on a grid of at most "
                 "1e-8 degrees or 1 mm (docs/output-format.md, Coordinates)");
  app.add_flag("--no-report", a.no_report, "do not write the run report");
  app.add_flag("--no-summary", a.no_summary, "do not write the summary CSV");
  app.add_option("--graph", a.graph,
                 "part graphs, one building per line (default: <stem>.morphcut.graph.jsonl)");
  app.add_flag("--no-graph", a.no_graph, "do not write the part graphs");
  app.add_option("--gpkg", a.gpkg,
                 "GeoPackage of building and part footprints (default: <stem>.morphcut.gpkg)");
  app.add_flag("--no-gpkg", a.no_gpkg, "do not write the GeoPackage");
  app.add_option("--html", a.html,
                 "HTML page of the run (default: the report's name with .report.json -> .html)");
  app.add_flag("--no-html", a.no_html, "do not write the HTML page");
  app.add_flag("--quiet,-q", a.quiet, "no progress bar and no final summary line on stderr");
  app.add_flag("--print-config", a.print_config,
               "print the effective configuration (defaults, then --config, then these options) as YAML with "
               "every key's help, and exit; with no --config it is config/lod.yaml");
  app.add_flag("--print-config-reference", a.print_reference,
               "print every key's type, default, range and meaning as Markdown tables (docs/config.md's), "
               "and exit");
  app.add_flag(
      "--no-fast-path", a.no_fast_path,
      "label every building by the full vote, also valid solids (config preprocess.fast_path: false; "
      "for A/B benchmarks)");
  app.set_version_flag("--version", MC_VERSION);
  app.footer(kFooter);
  return input_opt;
}

// The configuration: the file, then the options that override keys.
mc::LoadedConfig load_config(const CliArgs& a) {
  mc::LoadedConfig cfg;
  if (!a.config_path.empty()) cfg = mc::load_config_file(a.config_path);
  if (a.threads >= 0) cfg.params.threads = a.threads;
  if (a.timeout >= 0) cfg.params.timeout_s = a.timeout;
  if (!a.lod.empty()) cfg.run.lod = a.lod;
  if (a.no_fast_path) cfg.params.pre.fast_path = false;
  return cfg;
}

// Every output's path: given, or named after the input (current directory) or after -o.
mc::pipeline::RunOptions run_options(const CliArgs& a) {
  const bool sequence = a.input == "-" || a.input.ends_with(".jsonl");
  mc::pipeline::RunOptions opt;
  opt.input = a.input;
  opt.output = !a.output.empty()
                   ? a.output
                   : stem_of(a.input) + (sequence ? ".morphcut.city.jsonl" : ".morphcut.city.json");
  // The report and the summary go beside the output (`-o out/5910.city.json` gives
  // out/5910.morphcut.report.json), so a run with -o writes nothing into the current directory.
  const std::string stem = output_stem_of(a);
  opt.report = a.no_report ? "" : (!a.report.empty() ? a.report : stem + ".morphcut.report.json");
  opt.summary = a.no_summary ? "" : (!a.summary.empty() ? a.summary : stem + ".morphcut.csv");
  opt.graph = a.no_graph ? "" : (!a.graph.empty() ? a.graph : mc::report::graph_path_for_stem(stem));
  opt.gpkg = a.no_gpkg ? "" : (!a.gpkg.empty() ? a.gpkg : mc::report::gpkg_path_for_stem(stem));
  opt.config_file = a.config_path;
  opt.cache_dir = a.cache_dir;
  opt.output_crs = a.output_crs;
  opt.progress = !a.quiet && mc::pipeline::stderr_is_tty();
  opt.handle_signals = true;
  opt.crash_log = opt.output + ".crashed";
  return opt;
}

void log_result(const mc::pipeline::RunResult& r, const mc::pipeline::RunOptions& opt) {
  spdlog::info(
      "{} buildings ({} features) in {:.1f} s, {:.2f} buildings/s, {} threads: {} ok, {} partial, {} failed, "
      "{} skipped -> {}",
      r.buildings, r.features, r.wall_seconds, r.wall_seconds > 0 ? r.buildings / r.wall_seconds : 0.0,
      r.threads, r.counts.at("ok"), r.counts.at("partial"), r.counts.at("failed"), r.counts.at("skipped"),
      opt.output);
  if (!opt.cache_dir.empty())
    spdlog::info("cache {}: {} hits, {} misses, {} stored", opt.cache_dir, r.cache.hits, r.cache.misses,
                 r.cache.stored);
  for (const auto& p : r.reader_problems) spdlog::warn("input problem: {}", p);
}

// The HTML page, from the outputs just written (timed: it should stay a few % of the run). A page
// that cannot be made does not change the exit code: the run's outputs are complete.
void write_page(const CliArgs& a, const mc::pipeline::RunOptions& opt, const mc::pipeline::RunResult& r) {
  const std::string page = !a.html.empty()       ? a.html
                           : !opt.report.empty() ? mc::report::html_path_for_report(opt.report)
                                                 : output_stem_of(a) + ".morphcut.html";
  const auto t0 = std::chrono::steady_clock::now();
  try {
    const mc::report::HtmlReportResult h = mc::report::write_html_report(
        opt.report, opt.report.empty() ? std::vector<std::string>{opt.output} : std::vector<std::string>{},
        page);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    spdlog::info(
        "HTML page ({:.2f} MB, 3D for {} of {} buildings) in {:.2f} s, {:.1f}% of the run's {:.1f} s -> {}",
        static_cast<double>(h.bytes) / 1e6, h.with_3d, h.buildings, s,
        r.wall_seconds > 0 ? 100.0 * s / r.wall_seconds : 0.0, r.wall_seconds, h.path);
  } catch (const std::exception& e) { spdlog::error("HTML page not written: {}", e.what()); }
}

// The stem the side outputs are named after: the output's (without .morphcut), else the input's.
std::string output_stem_of(const CliArgs& a) {
  return !a.output.empty() ? output_stem(a.output) : stem_of(a.input);
}

// The decomposition run and its page; exceptions are the caller's.
int run(const CliArgs& a) {
  if (a.print_reference) {
    std::fputs(mc::config_reference_markdown().c_str(), stdout);
    return 0;
  }
  const mc::LoadedConfig cfg = load_config(a);
  if (a.print_config) {
    std::fputs(mc::config_yaml(cfg.params, cfg.run).c_str(), stdout);
    return 0;
  }
  const mc::pipeline::RunOptions opt = run_options(a);
  // The config's log_level decides what reaches stderr; --quiet keeps errors only.
  spdlog::level::level_enum level = spdlog::level::from_str(cfg.run.log_level);
  if (a.quiet) level = std::max(level, spdlog::level::err);
  spdlog::set_level(level);
  const mc::pipeline::RunResult r = mc::pipeline::run_city(opt, cfg.params, cfg.run);
  if (r.interrupted) {
    spdlog::error("interrupted (signal {}); no output written", r.interrupted);
    return r.exit_code();
  }
  log_result(r, opt);
  if (!a.no_html) write_page(a, opt, r);
  return r.exit_code();
}

}  // namespace

int main(int argc, char** argv) {
  // Messages go to stderr as "morphcut-city: ..." (spdlog's default logger would write to stdout).
  auto logger = spdlog::stderr_logger_st("morphcut-city");
  logger->set_pattern("morphcut-city: %v");
  spdlog::set_default_logger(logger);
  // Subcommands come first; anything else is an input path (a file named "validate" can be given
  // as ./validate).
  const std::string first = argc > 1 ? argv[1] : "";
  if (first == "validate") return mc::cli::validate_main(argc - 1, argv + 1);
  if (first == "merge-reports") return mc::cli::merge_reports_main(argc - 1, argv + 1);
  if (first == "html") return mc::cli::html_main(argc - 1, argv + 1);
  if (first == "reproject") return mc::cli::reproject_main(argc - 1, argv + 1);
  CLI::App app{"morphcut-city " MC_VERSION " - decompose every building of a CityJSON city into convex parts",
               "morphcut-city"};
  CliArgs a;
  CLI::Option* input_opt = declare_options(app, a);
  if (const auto code = mc::cli::parse_or_exit(app, argc, argv)) return *code;
  if (!a.print_config && !a.print_reference && input_opt->count() == 0) {
    app.exit(CLI::RequiredError(input_opt->get_name()));
    return mc::cli::kExitUsage;
  }
  try {
    return run(a);
  } catch (const mc::ConfigError& e) {
    spdlog::error("config: {}", e.what());
  } catch (const mc::io::ReadError& e) {
    spdlog::error("cannot read input: {}", e.what());
  } catch (const mc::io::WriteError& e) {
    spdlog::error("cannot write output: {}", e.what());
  } catch (const std::exception& e) { spdlog::error("error: {}", e.what()); }
  return mc::cli::kExitUsage;
}
