// The run's driver (pipeline/run.hpp): its input, its outputs, and the task graph between them.
#include <malloc.h>
#include "pipeline/run.hpp"

#include <atomic>
#include <chrono>
#include <exception>
#include <optional>

#include <tbb/flow_graph.h>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include "pipeline/building_task.hpp"
#include "pipeline/crash_guard.hpp"
#include "pipeline/feeder.hpp"
#include "pipeline/interrupt.hpp"
#include "pipeline/job_cpu.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/run_input.hpp"
#include "pipeline/run_outputs.hpp"
#include "pipeline/run_report.hpp"

namespace mc::pipeline {

using SteadyClock = std::chrono::steady_clock;

namespace {

double since(SteadyClock::time_point t0) {
  return std::chrono::duration<double>(SteadyClock::now() - t0).count();
}

// The writer node's step: one finished building into the output files, counted. Runs serially,
// in input order.
void write_outcome(Work& w, RunOutputs& outputs, Feeder& feeder, RunResult& res, size_t& flagged) {
  mc::report::BuildingOutcome& b = w.outcome;
  b.sequence = w.sequence;
  b.time.read = w.read_seconds;
  const auto t = SteadyClock::now();
  outputs.write_cities(b);
  feeder.written();  // (before the limiter is decremented: the feeder counts on it)
  b.time.write = since(t);
  ++res.features;
  // Under glibc's malloc (a build without jemalloc, docs/design.md "The allocator") freed geometry
  // stays in per-thread arenas; hand it back now and then so that resident memory stays flat over
  // a long city (the heap itself does not grow). Under jemalloc this finds nothing to do.
  if (res.features % 128 == 0) malloc_trim(0);
  if (b.is_building) {
    ++res.buildings;
    ++res.counts[b.status];
    flagged += b.status == "failed" || b.status == "partial";
    outputs.write_rows(b);
  }
}

// After the last building: the files committed, the reader's notes and the cache's counts kept,
// the report written.
void finish_run(const RunOptions& opt, const Params& params, const RunConfig& rc, RunInput& in,
                RunOutputs& outputs, BuildingCache* cache, SteadyClock::time_point start, RunResult& res) {
  outputs.commit_files();
  if (!in.header.coords_note.empty()) res.reader_problems.push_back(in.header.coords_note);
  if (!in.grid.note.empty()) res.reader_problems.push_back(in.grid.note);
  for (const auto& p : in.source->problems()) res.reader_problems.push_back(p);
  if (cache) res.cache = cache->stats();
  res.wall_seconds = since(start);
  res.peak_rss_mb = peak_rss_mb();
  if (outputs.has_report())
    outputs.commit_report(
        run_report(opt, params, rc, res, in, outputs, cache ? cache->dir() : std::string()));
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
  for (const char* s : mc::report::kStatuses) res.counts[s] = 0;
  res.threads = resolve_threads(params.threads);
  res.in_flight = effective_in_flight(rc, res.threads);
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, static_cast<size_t>(res.threads));

  RunInput in = open_run_input(opt);
  std::unique_ptr<BuildingCache> cache;
  if (!opt.cache_dir.empty()) cache = std::make_unique<BuildingCache>(opt.cache_dir, in.header, params, rc);
  RunOutputs outputs(opt, in.header, params, rc);
  Progress progress(opt.progress, feature_total(opt, *in.source));
  std::optional<InterruptWatchdog> watchdog;
  if (opt.handle_signals) watchdog.emplace(opt.interrupt_grace_s);
  const CrashGuard crash_guard(opt.crash_log);
  const TaskContext task{opt, in.header, params, rc, cache.get(), crash_guard, res.threads};

  // source (reader, serial) -> limiter (bounded in flight) -> job (parallel) -> sequencer (input
  // order) -> writer (serial) --decrement--> limiter.
  Feeder feeder(*in.source, static_cast<size_t>(res.in_flight), res.threads);
  std::exception_ptr write_error;
  std::atomic<bool> stop{false};
  size_t flagged = 0;
  tbb::flow::graph g;
  tbb::flow::input_node<Msg> source(g, [&](tbb::flow_control& fc) -> Msg {
    Msg w = stop.load() || interrupt_signal() ? Msg{} : feeder.next();
    if (!w) {
      if (feeder.error()) stop = true;
      fc.stop();
    }
    return w;
  });
  tbb::flow::limiter_node<Msg> limiter(g, static_cast<size_t>(res.in_flight));
  tbb::flow::function_node<Msg, Msg> job(g, tbb::flow::unlimited, [&](Msg w) -> Msg {
    struct OutOfTurn {  // however the job ends
      Feeder& feeder;
      bool counted;
      ~OutOfTurn() {
        if (counted) feeder.out_of_turn_done();
      }
    } out_of_turn{feeder, w->largest_first};
    if (stop.load() || interrupt_signal()) return w;  // nothing will be written: skip the work
    run_task(*w, task);
    return w;
  });
  tbb::flow::sequencer_node<Msg> order(g, [](const Msg& w) { return w->sequence; });
  tbb::flow::function_node<Msg, tbb::flow::continue_msg> write(g, tbb::flow::serial, [&](Msg w) {
    if (stop.load() || interrupt_signal()) return tbb::flow::continue_msg();
    try {
      write_outcome(*w, outputs, feeder, res, flagged);
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
  if (feeder.error()) std::rethrow_exception(feeder.error());
  if (write_error) std::rethrow_exception(write_error);

  finish_run(opt, params, rc, in, outputs, cache.get(), start, res);
  return res;
}

}  // namespace mc::pipeline
