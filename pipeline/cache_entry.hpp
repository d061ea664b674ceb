// A cached building outcome as JSON (pipeline/cache.hpp): every field of BuildingOutcome the
// writers and reports read, except the timings (those describe the run that reads the entry).
// NaN is stored as null. Reading throws (nlohmann::json exceptions or std::runtime_error) on
// anything missing or of the wrong type, so a damaged entry is never half-applied.
#pragma once
#include <nlohmann/json.hpp>

#include "report/outcome.hpp"

namespace mc::pipeline {

using mc::report::BuildingOutcome;

nlohmann::json outcome_to_json(const BuildingOutcome& b);
// Fills status, reason, lod, sizes, levels, measures, hausdorff and problems of `b`.
void outcome_from_json(const nlohmann::json& j, BuildingOutcome& b);

}  // namespace mc::pipeline
