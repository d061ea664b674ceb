// The input in the frame preprocessing works in (docs/algorithm.md §2): z up, the resolution
// (cell size c, δ, θa, the hair) derived from its extent, cleaned twice (for the oracle and for
// everything else), centred on its bounding box.
#pragma once
#include "core/params.hpp"
#include "core/polygon_mesh.hpp"
#include "core/preprocess.hpp"

namespace mc {

struct InputFrame {
  PolygonMesh mesh;         // cleaned (welded at min(δ/10, 1e-6 of the diagonal)), z-up, centred
  PolygonMesh oracle_mesh;  // welded only where positions coincide (1e-9 of the diagonal; §6.2)
  double diagonal = 0;      // of the raw input's bounding box
};

// Fills `out`'s frame and resolution (up_axis, cell_size, dist, angle_rad, hair, offset, box,
// labels) and the cleaning's problems. Throws std::runtime_error for input without a finite
// vertex, without extent, or without a valid face after cleaning.
InputFrame frame_input(const PolygonMesh& input, const PreprocessParams& p, Preprocessed& out);

}  // namespace mc
