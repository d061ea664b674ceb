// What a run reads (pipeline/run.hpp): the input as a stream of features (CityJSON, CityJSONSeq or
// CityGML; reprojected when --output-crs asks), the header the outputs are written with (its grid
// refined for degrees: output/output_grid.hpp), how many features come (for the progress line),
// and the input's SHA-256, computed beside the buildings.
#pragma once
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "io/feature_source.hpp"
#include "output/output_grid.hpp"

namespace mc::pipeline {

struct RunOptions;

struct RunInput {
  std::unique_ptr<mc::io::FeatureSource> source;
  mc::io::Header header;  // the outputs'
  mc::output::OutputGrid grid;
  std::future<std::string> sha256;  // empty string when unreadable or interrupted; invalid for stdin
};

// Throws mc::io::ReadError when the input cannot be opened or reprojected.
RunInput open_run_input(const RunOptions& opt);

// How many features the input holds, when known without reading them: the reader's count, or
// for a CityJSONSeq file with a progress line its non-empty lines after the first.
std::optional<size_t> feature_total(const RunOptions& opt, const mc::io::FeatureSource& source);

}  // namespace mc::pipeline
