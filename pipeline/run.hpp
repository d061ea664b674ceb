// A whole city through a TBB flow graph (docs/design.md, "Pipeline"):
//
//   source (reader, serial) -> limiter (bounded in flight) -> job (parallel) -> sequencer
//   (input order) -> writer (serial: CityJSON, report, CSV, progress) --decrement--> limiter
//
// The limiter is released only after a building is written, so buildings waiting in the
// sequencer count as in flight: memory stays bounded even when one slow building holds up the
// order. Output order = input order and every job is a pure function of its feature, so the
// outputs are byte-identical whatever the thread count.
#pragma once
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "config/run_config.hpp"
#include "core/params.hpp"
#include "io/cityjson_types.hpp"
#include "pipeline/cache.hpp"

namespace mc::pipeline {

struct RunOptions {
  std::string input;        // .city.json, .city.jsonl, or "-" (CityJSONSeq on stdin)
  std::string output;       // .jsonl = CityJSONSeq, else .city.json
  std::string report;       // empty = no run report
  std::string summary;      // empty = no summary CSV
  std::string graph;        // part graphs, one building per line (report/graph_export.hpp); empty = none
  std::string gpkg;         // GeoPackage of building and part footprints; empty = none
  std::string config_file;  // recorded in the report (empty = defaults)
  std::string cache_dir;    // per-building result cache (pipeline/cache.hpp); empty = none
  // Reproject the input to this CRS as it is read (io/reproject.hpp); empty = keep the input's.
  std::string output_crs;
  bool progress = false;  // draw the progress bar on stderr
  // Install SIGINT/SIGTERM handling (the CLI does). A first signal stops reading and writing,
  // leaves no output file, and the run returns with `interrupted` set; in-flight jobs get a
  // grace period, then the process exits with 128 + signal.
  bool handle_signals = false;
  double interrupt_grace_s = 3;
  // Crash log (pipeline/crash_guard.hpp): buildings that crashed an earlier run are written
  // through as failed, and a crash in this run is recorded there. Empty = no guard.
  std::string crash_log;
  // Test hook: called on each feature before its job (e.g. to break one building on purpose).
  std::function<void(mc::io::Feature&)> before_job;
};

struct RunResult {
  size_t features = 0, buildings = 0;
  std::map<std::string, size_t> counts;  // by status (ok, partial, failed, skipped)
  double wall_seconds = 0;
  int threads = 0, in_flight = 0;
  int interrupted = 0;  // the signal that stopped the run, or 0
  std::vector<std::string> reader_problems;
  double peak_rss_mb = 0;
  CacheStats cache;  // zeros without a cache
  // 0 every building ok (or skipped), 1 some failed or partial, 128 + signal when interrupted.
  int exit_code() const;
};

// Throws mc::io::ReadError / mc::io::WriteError for file-level failures (no output is left).
RunResult run_city(const RunOptions& opt, const Params& params, const RunConfig& rc);

// Worker threads for params.threads (0 = all cores).
int resolve_threads(int requested);

}  // namespace mc::pipeline
