// One building, start to finish: extraction at the configured LoD, preprocessing and
// decomposition under the per-building deadline, parts written into the feature.
// Never throws: every failure becomes a status with its reason (docs/reliability.md), so one bad
// building cannot stop a city.
#pragma once
#include "config/run_config.hpp"
#include "core/params.hpp"
#include "io/cityjson_types.hpp"
#include "report/outcome.hpp"

namespace mc::pipeline {

using mc::report::BuildingOutcome;

// Non-building features come back untouched with is_building = false. A building comes back
// with its BuildingParts (docs/output-format.md) and morphcut_* attributes; when the job fails or
// is skipped the input geometry is kept exactly, only the status attributes are added.
BuildingOutcome run_building(const mc::io::Feature& f, const mc::io::Header& h, const Params& p,
                             const RunConfig& rc);
// Same, taking the feature by value (the pipeline moves it through, no copy).
BuildingOutcome run_building(mc::io::Feature&& f, const mc::io::Header& h, const Params& p,
                             const RunConfig& rc);

// The input kept untouched with status "failed" and `reason`: for a job that threw outside
// run_building's own guard (the run's per-feature hook), so that the building is still written.
BuildingOutcome failed_building(mc::io::Feature&& f, const std::string& reason);

}  // namespace mc::pipeline
