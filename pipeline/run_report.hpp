// The run's own section of the report (docs/output-format.md): tool and version, the input (path,
// format, CRS, size, SHA-256), the outputs, the effective configuration, threads, times, memory,
// counts by status, the cache, the coordinates, the reader's problems. The buildings follow it
// (report/report.hpp).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "config/run_config.hpp"
#include "core/params.hpp"
#include "pipeline/run.hpp"
#include "pipeline/run_input.hpp"
#include "pipeline/run_outputs.hpp"

namespace mc::pipeline {

nlohmann::ordered_json run_report(const RunOptions& opt, const Params& params, const RunConfig& rc,
                                  const RunResult& res, RunInput& in, const RunOutputs& outputs,
                                  const std::string& cache_dir);

}  // namespace mc::pipeline
