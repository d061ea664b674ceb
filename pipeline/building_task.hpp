// One feature's work in a run's task graph: the crash log's verdict, the run's per-feature hook,
// the job itself (through the cache when there is one), its CPU time over every thread that helps
// it. Never throws: a failure becomes the building's status (pipeline/job.hpp).
#pragma once
#include "config/run_config.hpp"
#include "core/params.hpp"
#include "io/cityjson_types.hpp"
#include "pipeline/cache.hpp"
#include "pipeline/crash_guard.hpp"
#include "pipeline/feeder.hpp"

namespace mc::pipeline {

struct RunOptions;

struct TaskContext {
  const RunOptions& opt;
  const mc::io::Header& header;
  const Params& params;
  const RunConfig& rc;
  BuildingCache* cache = nullptr;  // none without --cache
  const CrashGuard& crash_guard;
  int threads = 1;
};

// Fills w.outcome from w.feature.
void run_task(Work& w, const TaskContext& ctx);

}  // namespace mc::pipeline
