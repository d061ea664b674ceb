// A building's levels written into its feature (docs/output-format.md): each written level's
// parts encoded on the output grid (pipeline/level_encoding.hpp); a level none of whose encodings
// is valid is replaced by a stand-in (the previous written level, a finer level, the singleton
// cell), noted; the staged parts committed to the feature at the end, nothing before.
#pragma once
#include <deque>
#include <string>
#include <vector>

#include "core/decompose.hpp"
#include "core/preprocess.hpp"
#include "core/working_frame.hpp"
#include "io/cityjson_common.hpp"
#include "pipeline/level_encoding.hpp"
#include "report/outcome.hpp"

namespace mc::pipeline {

// One level as written: its encoding, the parts it encodes (the level's, merged ones, or a
// stand-in's) and the stand-in's name (empty when none).
struct WrittenLevel {
  EncodedLevel e;
  const std::vector<PartResult>* parts = nullptr;
  std::string fallback;
};

class LevelWriter {
 public:
  // `grid_step`: the output grid's step near the building, in metres.
  LevelWriter(const std::string& building, const Preprocessed& pre, const Decomposition& dec,
              const std::vector<double>& thresholds, const std::string& lod, const std::string& version,
              const mc::io::Transform& transform, const WorkingFrame& frame, double grid_step);

  // Level i encoded (or its stand-in); `check_seconds` accumulates every attempt's checks.
  // Throws std::runtime_error when no stand-in is valid either.
  WrittenLevel encode(size_t i, double& check_seconds);
  // The level's parts staged for the feature, its outcome's search fields filled from the
  // decomposition when its own parts were written; returns the level's outcome.
  mc::report::LevelOutcome keep(WrittenLevel&& w, mc::report::BuildingOutcome& out);

  // Renumbers the staged parts' vertices after the feature's, adds them as the Building's
  // children (throws when an id exists already); fills out.size.parts_written and
  // output_vertices_added.
  void commit(mc::report::BuildingOutcome& out);

  bool fell_back() const { return fell_back_; }
  std::vector<std::string>& notes() { return notes_; }  // why the result is partial
  const std::vector<PolygonMesh>& first_level_meshes() const { return first_level_meshes_; }

 private:
  const std::string building_;
  const Preprocessed& pre_;
  const Decomposition& dec_;
  const std::vector<double>& thresholds_;
  const std::string lod_, version_;
  std::vector<Vec3> new_vertices_;
  mc::output::VertexPool pool_;
  const std::vector<PartResult> singleton_;
  std::vector<StagedPart> staged_;
  std::vector<PolygonMesh> first_level_meshes_;
  const std::vector<PartResult>* last_good_ = nullptr;  // the parts of the last level written
  std::vector<std::string> notes_;
  bool fell_back_ = false;
  // The last level encoded, before its massing attributes, with its parts (`relabelled`).
  std::optional<std::pair<EncodedLevel, const std::vector<PartResult>*>> reusable_;
  std::deque<std::vector<PartResult>> merged_levels_;  // parts of levels written with merged slivers
};

}  // namespace mc::pipeline
