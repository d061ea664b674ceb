// Preprocessing: rebuild a building as one watertight singleton cell (docs/algorithm.md §2–§8).
//
// clean soup -> centre (and rotate to z-up) -> plane segmentation -> plane registry ->
// Embree oracle -> iterative space carving of a convex cell complex -> interior cells,
// grouped into face-connected components (each is its own singleton cell; none is dropped
// unless it is below `min_component_fraction`, and drops are reported) -> fidelity (Hausdorff).
#pragma once
#include <chrono>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/complex.hpp"
#include "core/params.hpp"
#include "core/plane.hpp"
#include "core/polygon_mesh.hpp"

namespace mc {

using Clock = std::chrono::steady_clock;

struct SingletonComponent {
  std::vector<uint32_t> cells;  // live interior cells, ascending
  double volume = 0;
};

// The volume check of the singleton cell (docs/algorithm.md §6.5).
struct VolumeCheck {
  double estimate = -1;     // independent estimate of the volume the input encloses (< 0: none)
  double cell = 0;          // the kept cell's volume (all components)
  double ratio = 1;         // cell / estimate
  std::string method;       // of the estimate: "signed volume" (closed input) or "vertical columns"
  std::string oracle;       // the labelling kept: "parity" or "vertical"
  bool relabelled = false;  // the second labelling ran (disagreement, or no interior)
  bool flagged = false;     // the disagreement remains beyond the threshold
};

struct FidelityInputs;  // core/preprocess.cpp

struct Preprocessed {
  // Frame: complex coordinates c map to input coordinates by from_z_up(c + offset, up_axis).
  Vec3 offset;
  int up_axis = 2;
  double cell_size = 0, dist = 0;
  double angle_rad = 0;  // θa (plane classes, candidate snapping)
  // No plane may pass closer than this to a vertex without going through it (carving and cuts):
  // δ/10, or the output grid's step when that is larger (docs/algorithm.md §7.4).
  double hair = 0;
  BBox box;  // bounding box of the centred, z-up input (A_diag, snapping)
  // Held by pointer: the complex refers to the registry, so both must keep their address when a
  // Preprocessed is moved (e.g. assigned from preprocess()).
  std::unique_ptr<PlaneRegistry> planes = std::make_unique<PlaneRegistry>();
  std::unique_ptr<CellComplex> complex;
  std::vector<SingletonComponent> components;  // largest first
  std::vector<int32_t> plane_label;            // per plane id: semantic label index or -1
  std::vector<std::string> labels;             // label names (input labels)
  // Statistics.
  size_t input_faces = 0, regions = 0, cells = 0, inside_cells = 0, oracle_points = 0;
  size_t hole_planes = 0;      // planes of planar holes of the input (core/hole_planes.hpp)
  size_t anchored_planes = 0;  // planes snapped to a shared corner (core/corner_snap.hpp)
  size_t dropped_components = 0;
  double dropped_volume = 0;
  double hausdorff = -1, hausdorff_in_to_cell = -1, hausdorff_cell_to_in = -1, mean_distance = -1,
         mean_distance_cell_to_in = -1, mean_distance_symmetric = -1;
  bool closed = false, manifold = false;
  // Open input (docs/algorithm.md §6.4): boundary length not covered by other boundary edges.
  bool open_input = false;
  bool ground_from_terrain = false;  // the ground level came from terrain_z (roofs-only model)
  double open_boundary_length = 0;
  size_t boundary_wall_planes = 0;
  // Triangles of the floors added to the vertical vote where a part's ground is missing above the
  // lowest level (core/open_input.hpp: open_bottoms).
  size_t open_bottom_triangles = 0;
  VolumeCheck volume_check;
  // The input is a valid solid and the labelling took the fast path (docs/algorithm.md §6.6);
  // otherwise why not (the first validity error, "open input", or "fast path off").
  bool fast_path = false;
  std::string fast_path_reason;
  bool truncated = false;
  double seconds = 0;
  std::vector<std::string> problems;
  // What the fidelity measure needs when preprocess() defers it (measure_fidelity()): its own
  // copies, so that it may run while the decomposition changes the complex. Null otherwise.
  std::shared_ptr<FidelityInputs> pending_fidelity;

  Vec3 to_input(const Vec3& p) const;  // complex -> input coordinates
  int32_t label_of_plane(uint32_t plane) const {
    return plane < plane_label.size() ? plane_label[plane] : -1;
  }
};

// Throws std::runtime_error with a clear reason when no cell can be built (empty or degenerate
// input, nothing inside).
// `terrain_z` (input coordinates, NaN = unknown): the terrain height of the building's site, e.g.
// from a file attribute; used only as the ground level of a model without ground and walls
// (docs/algorithm.md §6.4).
// `defer_fidelity`: the Hausdorff measure of the cell against the input is left to
// measure_fidelity(), which the caller runs beside decompose() (decompose_measuring_fidelity(),
// core/decompose.hpp); otherwise preprocess() measures it before it returns.
Preprocessed preprocess(const PolygonMesh& input, const PreprocessParams& p, Clock::time_point deadline,
                        double terrain_z = std::numeric_limits<double>::quiet_NaN(),
                        bool defer_fidelity = false);

// Measures the fidelity that preprocess() deferred and fills `pre`'s Hausdorff fields; reads
// only `pre.pending_fidelity` (then released). Does nothing when nothing is pending.
void measure_fidelity(Preprocessed& pre);

}  // namespace mc
