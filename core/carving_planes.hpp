// The planes the carving cuts with, in their order (docs/algorithm.md §3–§5, §6.4): the fitted
// planes of the input's regions (snapped to shared corners), the planes of its holes and of an
// open boundary's missing walls (anchored on the lines of region planes they pass a hair from),
// and the ground cap last; with the padded carving box and the ground level of the vertical vote.
#pragma once
#include <vector>

#include "core/carve.hpp"
#include "core/hole_planes.hpp"
#include "core/input_frame.hpp"
#include "core/open_input.hpp"
#include "core/params.hpp"
#include "core/preprocess.hpp"

namespace mc {

struct CarvingPlanes {
  std::vector<CarvePlane> planes;    // in carving order
  BBox box;                          // the padded carving box
  double ground_z = 0;               // the ground level of the vertical vote (§6.4)
  std::vector<HolePlane> holes;      // the input's holes (their floors cap open bottoms)
  bool vertical_applicable = false;  // OpenInput::vertical_applicable()
  bool want_vertical = false;        // the vertical vote labels first (§6.4)
};

// Registers the planes in out.planes (their labels in out.plane_label) and creates out.complex
// over the carving box; fills out.regions, hole_planes, anchored_planes, boundary_wall_planes,
// ground_from_terrain, open_boundary_length and labels. `in.mesh` gains the ClosureSurface and
// GroundSurface labels of the virtual faces. `terrain_z` (input coordinates, NaN = unknown): the
// ground of a model without ground and walls. Throws std::runtime_error without any plane.
CarvingPlanes carving_planes(InputFrame& in, const OpenInput& open, const PreprocessParams& p,
                             double terrain_z, Preprocessed& out);

}  // namespace mc
