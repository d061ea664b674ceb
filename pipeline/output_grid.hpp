// The grid parts are written on (docs/output-format.md, "Coordinates"). Parts are new geometry:
// their vertices are intersections of planes, never on the input's grid, and a grid coarser than
// the checks' tolerances folds their slivers. The file's `transform` is kept when it is fine
// enough and refined by a power of ten otherwise, so that every input vertex stays exactly on the
// new grid: at most 1e-8 degrees (about 1.1 mm) for geographic coordinates, at most 1 mm of height.
#pragma once
#include <string>

#include "core/vec3.hpp"
#include "io/cityjson_types.hpp"

namespace mc::pipeline {

struct OutputGrid {
  bool present = false;  // the file has a transform (CityJSON 1.0 files may not)
  bool refined = false;
  Vec3 input_scale, scale;
  std::string note;  // what was refined and why; empty when nothing was
};

// Refines `h.root["transform"]` in place where it is coarser than the limits above.
OutputGrid refine_output_grid(mc::io::Header& h);

}  // namespace mc::pipeline
