// Every algorithm parameter with its default. The configuration keys are declared once, in
// core/params.def (type, name, default, range, help); the members below expand from it, beside the
// few settings that are not keys. config/ fills this from YAML (or from the paper's per-sample
// `NAME.off_config.json`); core/ only reads it. Reference: docs/config.md.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mc {

struct PreprocessParams {
#define MC_PREPROCESS_KEY(type, name, def, kind, range, help) type name = def;
#include "core/params.def"
  // The output grid's step near the building (model units), set per file by the pipeline from the
  // output's transform (not a configuration key; 0 = none). No plane may pass closer than one step
  // to a vertex without going through it, nor a hair-blocked plane cut closer than two steps: such
  // vertices would collapse on the grid (docs/algorithm.md §7.4).
  double output_grid = 0;
  // With the fast path, a cell the surface only grazes is voted in a band along its facets
  // (docs/algorithm.md §7.3). Not a configuration key: tests compare with the full vote.
  bool grazed_cells = true;
  // The parity vote labels the points of a cell the surface touches by regions: boxes of them
  // that no triangle touches are decided by a few points each (docs/design.md "Regions, not
  // points"). Not a configuration key: tests and benchmarks compare with the point-by-point vote.
  bool region_votes = true;
  // With the fast path, a cell the surface touches is labelled by its exact inside volume (the
  // surface's columns over it, core/column_volume.hpp) instead of sample points (docs/design.md
  // "Inside volume by columns"). Not a configuration key: tests compare with the votes.
  bool column_volumes = true;
  // The fidelity measure's mean distances (core/hausdorff.hpp) besides its maxima. Not a
  // configuration key: `morphcut` reports them; the city pipeline reports the maxima only and
  // turns them off, which skips most of the measure's closest-point queries.
  bool mean_distances = true;
};

struct DecomposeParams {
#define MC_DECOMPOSE_KEY(type, name, def, kind, range, help) type name = def;
#include "core/params.def"
};

// Massing analytics of the written parts (massing/massing.hpp, docs/massing.md): contact
// kinds, part roles and building features. Lengths in model units, angles in degrees.
struct MassingParams {
#define MC_MASSING_KEY(type, name, def, kind, range, help) type name = def;
#include "core/params.def"
};

struct Params {
  PreprocessParams pre;
  DecomposeParams dec;
  MassingParams massing;
#define MC_TOP_KEY(type, name, def, kind, range, help) type name = def;
#include "core/params.def"
};

}  // namespace mc
