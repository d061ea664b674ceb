#include <malloc.h>
#include "pipeline/run.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <tbb/flow_graph.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>

#include "config/config.hpp"
#include "io/cityjson.hpp"
#include "io/crs.hpp"
#include "io/feature_source.hpp"
#include "io/reproject.hpp"
#include "io/temp_registry.hpp"
#include "pipeline/cache.hpp"
#include "pipeline/crash_guard.hpp"
#include "pipeline/interrupt.hpp"
#include "pipeline/job.hpp"
#include "pipeline/job_cpu.hpp"
#include "output/level_views.hpp"
#include "output/output_grid.hpp"
#include "pipeline/progress.hpp"
#include "report/report.hpp"
#include "io/sha256.hpp"
#include "report/summary_csv.hpp"
#include "report/graph_export.hpp"

namespace mc::pipeline {
using namespace mc::massing;

using namespace mc::output;
using namespace mc::report;

using nlohmann::json;
using SteadyClock = std::chrono::steady_clock;
// Features read ahead of the writer, among which the largest is started first (at least the
// in-flight window).
constexpr size_t kLookAhead = 256;
// and at most this many vertices among them beyond the window (a parsed feature takes about
// 0.75 kB per vertex: this bounds the look-ahead's memory at about 25 MB whatever the buildings).
constexpr size_t kLookAheadVertices = 32768;

namespace {

double since(SteadyClock::time_point t0) {
  return std::chrono::duration<double>(SteadyClock::now() - t0).count();
}

struct Work {
  size_t sequence = 0;
  bool largest_first = false;  // started ahead of its turn because it was the largest read
  double read_seconds = 0;
  mc::io::Feature feature;
  BuildingOutcome outcome;
};
using Msg = std::shared_ptr<Work>;

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

// Features in a CityJSONSeq file = non-empty lines after the first; for the progress bar only.
std::optional<size_t> count_sequence_features(const std::string& path) {
  std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!f) return std::nullopt;
  size_t lines = 0;
  bool content = false;
  std::vector<char> buf(1 << 20);
  size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), f.get())) > 0)
    for (size_t i = 0; i < n; ++i) {
      if (buf[i] == '\n') {
        lines += content;
        content = false;
      } else if (buf[i] != ' ' && buf[i] != '\r' && buf[i] != '\t') {
        content = true;
      }
    }
  lines += content;
  return lines > 0 ? std::optional<size_t>(lines - 1) : std::nullopt;
}

// After a signal, in-flight jobs cannot be cancelled (core only knows deadlines); give them a
// grace period, then leave without outputs (temp files are unlinked first).
class InterruptWatchdog {
 public:
  explicit InterruptWatchdog(double grace_s) : grace_(grace_s), thread_([this] { loop(); }) {}
  ~InterruptWatchdog() {
    {
      std::lock_guard lock(m_);
      done_ = true;
    }
    cv_.notify_all();
    thread_.join();
  }

 private:
  void loop() {
    std::unique_lock lock(m_);
    std::optional<SteadyClock::time_point> since_signal;
    while (!done_) {
      cv_.wait_for(lock, std::chrono::milliseconds(50));
      if (done_) break;
      if (const int sig = interrupt_signal()) {
        if (!since_signal) since_signal = SteadyClock::now();
        if (since(*since_signal) > grace_) {
          mc::io::unlink_registered_temp_files();
          std::fprintf(stderr, "\nmorphcut-city: interrupted; buildings still running were abandoned\n");
          _exit(128 + sig);
        }
      }
    }
  }
  double grace_;
  std::mutex m_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};

// The report's account of the coordinates: the input's CRS and units, the metric frame the
// buildings were decomposed in, and what the outputs are written in.
nlohmann::ordered_json coordinates_json(const mc::io::Header& input, const mc::io::Header& output,
                                        const OutputGrid& grid) {
  using ojson = nlohmann::ordered_json;
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

int RunResult::exit_code() const {
  if (interrupted) return 128 + interrupted;
  auto get = [&](const char* s) {
    auto it = counts.find(s);
    return it == counts.end() ? size_t(0) : it->second;
  };
  return get("failed") + get("partial") > 0 ? 1 : 0;
}

int resolve_threads(int requested) {
  return requested > 0 ? requested : std::max(1, tbb::info::default_concurrency());
}

RunResult run_city(const RunOptions& opt, const Params& params, const RunConfig& rc) {
  const auto start = SteadyClock::now();
  if (opt.handle_signals) install_interrupt_handlers();
  RunResult res;
  for (const char* s : kStatuses) res.counts[s] = 0;
  res.threads = resolve_threads(params.threads);
  res.in_flight = effective_in_flight(rc, res.threads);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(res.threads));

  // The input hash runs beside the buildings (the only other reader of the file).
  std::future<std::string> hash;
  // It gives up on an interrupt, so that stopping never waits for a gigabyte to be hashed.
  if (opt.input != "-")
    hash = std::async(std::launch::async, [p = opt.input] {
      std::unique_ptr<FILE, int (*)(FILE*)> f(std::fopen(p.c_str(), "rb"), &std::fclose);
      if (!f) return std::string();
      mc::io::Sha256 sha;
      std::vector<char> buf(1 << 20);
      size_t n;
      while ((n = std::fread(buf.data(), 1, buf.size(), f.get())) > 0) {
        if (interrupt_signal()) return std::string();
        sha.update(buf.data(), n);
      }
      return std::ferror(f.get()) ? std::string() : sha.hex();
    });

  // CityJSON, CityJSONSeq or CityGML (by extension): the graph below only sees Features.
  std::unique_ptr<mc::io::FeatureSource> source_file = mc::io::open_feature_source(opt.input);
  if (!opt.output_crs.empty()) {
    try {
      source_file = std::make_unique<mc::io::ReprojectedSource>(std::move(source_file), opt.output_crs);
    } catch (const mc::io::ReadError&) { throw; } catch (const std::exception& e) {
      throw mc::io::ReadError("--output-crs " + opt.output_crs + ": " + e.what());
    }
  }
  mc::io::FeatureSource& reader = *source_file;
  mc::io::Header header = reader.header();
  // Coordinates (docs/output-format.md, "Coordinates"): the grid the parts are written on.
  const OutputGrid grid = refine_output_grid(header);
  std::unique_ptr<BuildingCache> cache;
  if (!opt.cache_dir.empty()) cache = std::make_unique<BuildingCache>(opt.cache_dir, header, params, rc);
  const mc::io::CrsTransformer crs(header.crs);

  // All outputs are opened first, so a bad path fails before any work is done: the annotated
  // input and one city per written level (output/level_views.hpp, docs/output-format.md).
  mc::io::CityJsonWriter writer(opt.output, header);
  std::vector<double> written_levels;
  for (size_t i = 0; i < params.dec.levels.size(); ++i)
    if (writes_level(rc, i)) written_levels.push_back(params.dec.levels[i]);
  std::vector<std::unique_ptr<mc::io::CityJsonWriter>> level_writers;
  for (double t : written_levels)
    level_writers.push_back(
        std::make_unique<mc::io::CityJsonWriter>(level_output_path(opt.output, t), header));
  std::unique_ptr<ReportWriter> report;
  std::unique_ptr<SummaryWriter> summary;
  if (!opt.report.empty()) report = std::make_unique<ReportWriter>(opt.report);
  // Centroids to 0.1 mm: 3 decimals of metres, 9 of degrees.
  const int decimals = header.coords.geographic() ? 9 : 3;
  if (!opt.summary.empty()) summary = std::make_unique<SummaryWriter>(opt.summary, written_levels, decimals);
  std::unique_ptr<GraphWriter> graph;  // massing analytics (docs/massing.md)
  std::unique_ptr<MassingGpkgWriter> gpkg;
  if (!opt.graph.empty()) graph = std::make_unique<GraphWriter>(opt.graph);
  if (!opt.gpkg.empty())
    gpkg = std::make_unique<MassingGpkgWriter>(opt.gpkg, header.crs, written_levels, decimals);

  std::optional<size_t> total = reader.feature_count();
  if (!total && opt.progress && opt.input != "-" && opt.input.ends_with(".jsonl"))
    total = count_sequence_features(opt.input);
  Progress progress(opt.progress, total);
  std::optional<InterruptWatchdog> watchdog;
  if (opt.handle_signals) watchdog.emplace(opt.interrupt_grace_s);

  const CrashGuard crash_guard(opt.crash_log);
  std::exception_ptr read_error, write_error;
  std::atomic<bool> stop{false};
  size_t next_sequence = 0, flagged = 0;

  // Largest first (docs/design.md, "Largest buildings first"): the source reads up to `in_flight`
  // features ahead and starts the one with the most vertices, so a large building does not start
  // last and leave the other cores idle at the end. Outputs keep the input order (the sequencer).
  // The buildings started but not written are bounded by the limiter; when it is one short of full,
  // the source starts the lowest waiting sequence instead, so the building the writer waits for is
  // always among those in flight (never a deadlock), and memory stays bounded by `in_flight`.
  std::vector<Msg> ahead;  // read, not started; the source body runs on one thread at a time
  bool input_done = false;
  size_t started = 0;
  std::atomic<size_t> written{0};
  const size_t window = static_cast<size_t>(res.in_flight);
  // The source looks further ahead than the window, so a large building starts long before the
  // writer needs it (not when it enters the window, where the window could fill up with small
  // buildings finished behind it and leave cores idle), and at most threads - 1 buildings run out
  // of turn, so the others keep the writer going (docs/design.md, "Largest buildings first").
  const size_t look_ahead = std::max(window, kLookAhead);
  const int max_largest_first = std::max(1, res.threads - 1);
  std::atomic<int> largest_running{0};
  size_t ahead_vertices = 0;
  tbb::flow::graph g;
  tbb::flow::input_node<Msg> source(g, [&](tbb::flow_control& fc) -> Msg {
    if (stop.load() || interrupt_signal()) {
      fc.stop();
      return {};
    }
    while (!input_done &&
           (ahead.size() < window || (ahead.size() < look_ahead && ahead_vertices < kLookAheadVertices))) {
      auto w = std::make_shared<Work>();
      const auto t = SteadyClock::now();
      try {
        if (!reader.next(w->feature)) {
          input_done = true;
          break;
        }
      } catch (...) {
        read_error = std::current_exception();
        stop = true;
        fc.stop();
        return {};
      }
      w->read_seconds = since(t);
      w->sequence = next_sequence++;
      ahead_vertices += w->feature.vertices.size();
      ahead.push_back(std::move(w));
    }
    if (ahead.empty()) {
      fc.stop();
      return {};
    }
    auto lowest = [](const Msg& a, const Msg& b) { return a->sequence < b->sequence; };
    auto pick = std::min_element(ahead.begin(), ahead.end(), lowest);
    const bool largest = started - written.load() + 1 < window && largest_running.load() < max_largest_first;
    if (largest) {
      pick = std::min_element(ahead.begin(), ahead.end(), [](const Msg& a, const Msg& b) {
        const size_t na = a->feature.vertices.size(), nb = b->feature.vertices.size();
        return na != nb ? na > nb : a->sequence < b->sequence;
      });
      (*pick)->largest_first = true;
      ++largest_running;
    }
    Msg w = std::move(*pick);
    ahead.erase(pick);
    ahead_vertices -= w->feature.vertices.size();
    ++started;
    return w;
  });
  tbb::flow::limiter_node<Msg> limiter(g, static_cast<size_t>(res.in_flight));
  tbb::flow::function_node<Msg, Msg> job(g, tbb::flow::unlimited, [&](Msg w) -> Msg {
    struct OutOfTurn {  // however the job ends
      std::atomic<int>& running;
      bool counted;
      ~OutOfTurn() {
        if (counted) --running;
      }
    } out_of_turn{largest_running, w->largest_first};
    if (stop.load() || interrupt_signal()) return w;  // nothing will be written: skip the work
    if (std::string why = crash_guard.skip_reason(w->feature.id); !why.empty()) {
      w->outcome = failed_building(std::move(w->feature), why);
      return w;
    }
    const CrashGuard::Scope running(w->feature.id);  // a crash from here on names this building
    // An exception escaping a job would cancel the whole graph: the building fails instead.
    try {
      if (opt.before_job) opt.before_job(w->feature);
    } catch (const std::exception& e) {
      w->outcome = failed_building(std::move(w->feature), e.what());
      return w;
    } catch (...) {
      w->outcome = failed_building(std::move(w->feature), "unknown exception");
      return w;
    }
    auto building = [&] {
      return cache ? cache->run(std::move(w->feature), header, params, rc)
                   : run_building(std::move(w->feature), header, params, rc);
    };
    const double cpu0 = thread_cpu_seconds();
    double helpers = 0;  // CPU seconds of other threads in the building's arena
    // A building started out of turn (the largest read) runs in an arena of high priority: a thread
    // that finishes a small building helps with its parallel steps before it takes the next one,
    // so the largest building takes about its time alone (docs/design.md, "Largest buildings
    // first").
    if (w->largest_first && res.threads > 1) {
      tbb::task_arena heavy(res.threads, 1, tbb::task_arena::priority::high);
      ArenaWorkerCpu workers(heavy);
      w->outcome = heavy.execute(building);
      helpers = workers.close();
    } else {
      w->outcome = building();
    }
    w->outcome.time.cpu = thread_cpu_seconds() - cpu0 + helpers;
    return w;
  });
  tbb::flow::sequencer_node<Msg> order(g, [](const Msg& w) { return w->sequence; });
  tbb::flow::function_node<Msg, tbb::flow::continue_msg> write(g, tbb::flow::serial, [&](Msg w) {
    if (stop.load() || interrupt_signal()) return tbb::flow::continue_msg();
    BuildingOutcome& b = w->outcome;
    b.sequence = w->sequence;
    b.time.read = w->read_seconds;
    const auto t = SteadyClock::now();
    try {
      if (b.is_building) {
        writer.write(annotated_view(b.feature));
        for (size_t l = 0; l < level_writers.size(); ++l)
          level_writers[l]->write(level_view(b.feature, header, written_levels[l], b.lod));
      } else {
        writer.write(b.feature);
        for (auto& lw : level_writers) lw->write(b.feature);
      }
      b.feature = mc::io::Feature{};  // release the geometry before the reports
      ++written;                      // (before the limiter is decremented: the source counts on it)
      b.time.write = since(t);
      ++res.features;
      // Freed geometry stays in glibc's per-thread arenas; hand it back now and then so that
      // resident memory stays flat over a long city (the heap itself does not grow).
      if (res.features % 128 == 0) malloc_trim(0);
      if (b.is_building) {
        ++res.buildings;
        ++res.counts[b.status];
        flagged += b.status == "failed" || b.status == "partial";
        if (b.measures.centroid && crs.valid())
          b.measures.lonlat =
              crs.to_lonlat(b.measures.centroid->x, b.measures.centroid->y, b.measures.centroid->z);
        if (report) report->add(b);
        if (summary) summary->add(b);
        if (graph) graph->add(b);
        if (gpkg) gpkg->add(b);
      }
    } catch (...) {
      write_error = std::current_exception();
      stop = true;
    }
    progress.update(res.features, flagged);
    return tbb::flow::continue_msg();
  });
  tbb::flow::make_edge(source, limiter);
  tbb::flow::make_edge(limiter, job);
  tbb::flow::make_edge(job, order);
  tbb::flow::make_edge(order, write);
  tbb::flow::make_edge(write, limiter.decrementer());
  source.activate();
  g.wait_for_all();
  progress.finish();

  res.interrupted = interrupt_signal();
  if (res.interrupted) return res;  // writers die uncommitted: no output files appear
  if (read_error) std::rethrow_exception(read_error);
  if (write_error) std::rethrow_exception(write_error);

  writer.close();
  for (auto& lw : level_writers) lw->close();
  if (summary) summary->commit();
  if (graph) graph->commit();
  if (gpkg) gpkg->commit();
  if (!header.coords_note.empty()) res.reader_problems.push_back(header.coords_note);
  if (!grid.note.empty()) res.reader_problems.push_back(grid.note);
  for (const auto& p : reader.problems()) res.reader_problems.push_back(p);
  if (cache) res.cache = cache->stats();
  res.wall_seconds = since(start);
  res.peak_rss_mb = peak_rss_mb();
  if (report) {
    std::string sha;
    if (hash.valid()) { sha = hash.get(); }
    std::error_code ec;
    const auto bytes = opt.input == "-" ? 0 : std::filesystem::file_size(opt.input, ec);
    using ojson = nlohmann::ordered_json;
    ojson counts = ojson::object();
    for (const char* s : kStatuses) counts[s] = res.counts[s];
    ojson level_outputs = ojson::array();
    for (double t : written_levels)
      level_outputs.push_back({{"threshold", t}, {"cityjson", level_output_path(opt.output, t)}});
    ojson run = {{"tool", "morphcut-city"},
                 {"version", MC_VERSION},
                 {"input",
                  {{"path", opt.input},
                   {"format", reader.format()},
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
                 {"cache", cache ? ojson{{"dir", cache->dir()},
                                         {"hits", res.cache.hits},
                                         {"misses", res.cache.misses},
                                         {"stored", res.cache.stored},
                                         {"not_stored", res.cache.not_stored},
                                         {"corrupt", res.cache.corrupt},
                                         {"store_errors", res.cache.store_errors}}
                                 : ojson(nullptr)},
                 {"crs_for_wgs84", crs.valid() ? ojson(header.crs) : ojson(nullptr)},
                 {"coordinates", coordinates_json(reader.header(), header, grid)},
                 {"reader_problems", res.reader_problems},
                 {"dropped_feature_extras", writer.dropped_extras()}};
    if (!crs.valid() && !header.crs.empty()) run["crs_error"] = crs.error();
    report->commit(run);
  }
  return res;
}

}  // namespace mc::pipeline
