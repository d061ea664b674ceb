// Range and consistency checks on a filled-in configuration, wherever it came from (YAML, the
// paper's JSON, command-line overrides). Throws ConfigError naming the YAML key path.
#pragma once
#include "config/run_config.hpp"
#include "core/params.hpp"

namespace mc {

void check_config(const Params& params, const RunConfig& run);

}  // namespace mc
