#include "pipeline/building_task.hpp"

#include <exception>

#include <tbb/task_arena.h>

#include "pipeline/job.hpp"
#include "pipeline/job_cpu.hpp"
#include "pipeline/run.hpp"

namespace mc::pipeline {

void run_task(Work& w, const TaskContext& ctx) {
  if (std::string why = ctx.crash_guard.skip_reason(w.feature.id); !why.empty()) {
    w.outcome = failed_building(std::move(w.feature), why);
    return;
  }
  const CrashGuard::Scope running(w.feature.id);  // a crash from here on names this building
  // An exception escaping a job would cancel the whole graph: the building fails instead.
  try {
    if (ctx.opt.before_job) ctx.opt.before_job(w.feature);
  } catch (const std::exception& e) {
    w.outcome = failed_building(std::move(w.feature), e.what());
    return;
  } catch (...) {
    w.outcome = failed_building(std::move(w.feature), "unknown exception");
    return;
  }
  auto building = [&] {
    return ctx.cache ? ctx.cache->run(std::move(w.feature), ctx.header, ctx.params, ctx.rc)
                     : run_building(std::move(w.feature), ctx.header, ctx.params, ctx.rc);
  };
  const double cpu0 = thread_cpu_seconds();
  double helpers = 0;  // CPU seconds of other threads in the building's arena
  // A building started out of turn (the largest read) runs in an arena of high priority: a thread
  // that finishes a small building helps with its parallel steps before it takes the next one,
  // so the largest building takes about its time alone (docs/design.md, "Largest buildings
  // first").
  if (w.largest_first && ctx.threads > 1) {
    tbb::task_arena heavy(ctx.threads, 1, tbb::task_arena::priority::high);
    ArenaWorkerCpu workers(heavy);
    w.outcome = heavy.execute(building);
    helpers = workers.close();
  } else {
    w.outcome = building();
  }
  w.outcome.time.cpu = thread_cpu_seconds() - cpu0 + helpers;
}

}  // namespace mc::pipeline
