// The grid parts are written on (docs/output-format.md, "Coordinates"). A file in metres (or
// feet) keeps its `transform`: the decomposition makes its parts fit that grid (no vertex closer
// to a plane than one step: docs/algorithm.md §7.4). A geographic file's grid is refined by a
// power of ten, so that every input vertex stays exactly on the new grid, to at most 1e-8 degrees
// (about 1.1 mm) and 1 mm of height: CityGML input gets a default grid of 0.001 units, and a grid
// of degrees chosen for display says nothing about the parts.
#pragma once
#include <string>

#include "core/vec3.hpp"
#include "core/working_frame.hpp"
#include "io/cityjson_common.hpp"
#include "io/cityjson_types.hpp"

namespace mc::output {

struct OutputGrid {
  bool present = false;  // the file has a transform (CityJSON 1.0 files may not)
  bool refined = false;
  Vec3 input_scale, scale;
  std::string note;  // what was refined and why; empty when nothing was
};

// Refines `h.root["transform"]` in place where it is coarser than the limits above.
OutputGrid refine_output_grid(mc::io::Header& h);

// The largest step of the grid `t` near `file_point`, in metres of the working frame (one step
// of each axis mapped by `frame`); 0 without a transform.
double grid_step_metres(const mc::io::Transform& t, const WorkingFrame& frame, const Vec3& file_point);

}  // namespace mc::output
