// One level's parts encoded on the output grid and checked, staged before they touch the
// building's feature (so that a failure half-way leaves the input exactly as it was), with every
// repair that keeps a level from falling back: vertex clustering, near-touching vertices moved,
// each part from its own mesh, slivers merged into neighbours (docs/output-format.md §Repairs).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/decompose.hpp"
#include "core/preprocess.hpp"
#include "output/part_objects.hpp"
#include "report/outcome.hpp"

namespace mc::pipeline {

// "<building>-mc<level index>-<part index>".
std::string part_id(const std::string& building, size_t level, size_t index);

struct StagedPart {
  std::string id;
  nlohmann::json object;
};

struct EncodedLevel {
  std::vector<StagedPart> staged;
  std::vector<PolygonMesh> meshes;
  mc::report::LevelOutcome lv;  // the geometric fields; the search fields are the caller's
  size_t dropped_faces = 0, repaired_parts = 0, split_faces = 0;
  std::string grid_repair;  // LevelOutcome::grid_repair
  double check_seconds = 0;
  std::string defect;    // non-empty: a part fails the checks, and nothing of the level is kept
  int failed_part = -1;  // the part the defect is on
  // The parts actually encoded when slivers were merged into neighbours (output/part_merge.hpp).
  std::optional<std::vector<PartResult>> merged;
};

// A level whose parts are the parts of the level encoded before it is encoded exactly as that one
// (the same meshes, vertices already in the pool, the same checks and repairs): its encoding is
// that level's under its own ids, level and neighbour ids. Most small buildings keep their parts
// over several levels (docs/benchmarks.md, "Speed").
EncodedLevel relabelled(const EncodedLevel& previous, const std::string& building, size_t i, double threshold,
                        const std::vector<PartResult>& parts);

// Level i's parts on the grid, every repair tried; on failure the pool is back at its mark and
// the first defect is reported.
EncodedLevel encode_level_on_grid(const std::string& building, size_t i, double threshold,
                                  const std::vector<PartResult>& parts, const Preprocessed& pre,
                                  const std::string& lod, const std::string& version,
                                  mc::output::VertexPool& pool);

}  // namespace mc::pipeline
