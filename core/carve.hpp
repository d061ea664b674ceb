// Iterative, inconsistency-guided space carving (docs/algorithm.md §7).
//
// The padded bounding box is split by the building's region planes, largest first; each cell is
// labelled inside/outside by voting over sample points with the ray-casting oracle (a valid
// solid's touched cells by their exact inside volume instead), and cells whose vote is not
// unanimous (their "inconsistent volume") are split further while planes that really cross them
// remain. Departures from the research code, each for robustness:
//  - a plane is offered to a cell only if some vertex lies more than δ on each side (no slivers)
//    and the region's bounding box (grown by 3δ) overlaps the cell's;
//  - sample points are quasi-random (R3 sequence) and uniform in a fan tetrahedralisation;
//  - the re-queue threshold scales with the cell size (c³), not an absolute 1e-3 m³.
#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "core/column_volume.hpp"
#include "core/complex.hpp"
#include "core/surface_index.hpp"

namespace mc {

struct CarvePlane {
  uint32_t plane;  // registry id
  BBox bbox;       // bounding box of the region's faces
};

struct CarveParams {
  double cell_size = 1;  // c
  double dist = 0.25;    // δ
  BBox oracle_box;       // beyond it every point is outside (invalid: no such box)
  int min_points = 100;
  int max_points = 10000;
  double inside_vote = 0.5;
  double inconsistency = 1e-3;  // times c³
  size_t max_cells = 50000;
  int vote_batch = 9;      // points deciding a cell the surface does not touch (0 = full vote)
  double min_gap = 0.002;  // see PreprocessParams::min_gap
  double hair = -1;        // see Preprocessed::hair; < 0: δ/10
  double hair_or_default() const { return hair >= 0 ? hair : 0.1 * dist; }
  // Whether the input surface touches a box (conservative); null = always full votes.
  std::function<bool(const BBox&)> surface_touches;
  // For a valid solid (docs/algorithm.md §7.3, "grazed cells"): the input surface, to tell whether
  // it reaches deeper than `graze_depth` (fitting noise) into the convex cell {x : n·x + d <= 0
  // for every outward facet plane}. A cell it does not is uniform except in a band along its
  // facets: only the sample points within `band` of a facet are voted, and `vote_batch` of the
  // others decide the rest. Null = every touched cell gets the full vote.
  const SurfaceIndex* grazing = nullptr;
  double graze_depth = 0;
  double band = 0;
  // When set, touched cells are voted by regions (boxes of their points that no triangle of
  // this index touches, and that do not straddle `oracle_box`, are decided by `vote_batch`
  // points each) instead of point by point. Only for an oracle that is constant where the
  // surface does not pass (the parity vote).
  const SurfaceIndex* regions = nullptr;
  // For a valid solid: the volume of a convex cell (its outward facet loops and box) inside the
  // input surface, exact up to rounding (core/column_volume.hpp), or < 0 when it would cost more
  // than a vote (a large cell under many triangles). When set, a cell the surface touches is
  // labelled by it instead of by sample points; untouched cells keep their few points.
  std::function<double(const ConvexPolytope&, const BBox&)> inside_volume;
  uint64_t seed = 1;
};

// Classifies points (inside = 1); a point's id seeds its ray jitter deterministically.
using PointClassifier =
    std::function<void(const std::vector<Vec3>&, const std::vector<uint64_t>& ids, std::vector<uint8_t>&)>;

// A cell without a vote's share (CarveResult::inside_share): taken as unanimous for its label.
constexpr float kNoShare = -1.0f;

struct CarveResult {
  std::vector<uint32_t> inside;  // live inside cells, ascending ids
  size_t cells = 0;              // live cells at the end
  size_t splits = 0;
  size_t points = 0;       // oracle queries
  bool truncated = false;  // stopped by max_cells or the deadline
  // Per cell id: the inside share r of its last vote (complete for every live cell), or kNoShare.
  std::vector<float> inside_share;
};

CarveResult carve(CellComplex& cx, const std::vector<CarvePlane>& planes, const PointClassifier& classify,
                  const CarveParams& p, std::chrono::steady_clock::time_point deadline);

// A vote's count: its points inside and outside. An incomplete count (a vote stopped once the
// cell is known to be inconsistent) holds lower bounds of both.
struct RegionCount {
  size_t in = 0;
  size_t out = 0;
  bool complete = true;
};

// The vote by regions (docs/design.md "Regions, not points"): how many of a cell's sample points
// `pts` (ids first_id + i) are inside. A box of points that no triangle of `triangles` (those
// entering the cell) touches and that does not straddle `oracle_box` lies in one convex region
// the surface does not cross: its first `batch` points are classified and, when they agree,
// label all of its points. Where they disagree (the oracle is not constant there: rays escaping
// through gaps of an open or non-manifold input) every point of the box is classified. When the
// triangles in a box lie within `slab` of one plane, its points beyond the slab on either side
// are two such regions. Points of the other boxes (at most `batch` each, near the surface) are
// classified one by one. Adds the oracle's queries to `classified`. With `mixed_at` > 0 the
// count stops (incomplete) once the untouched regions' representatives settle at least
// `mixed_at` points of each label: the points near the surface are not classified, since the
// cell will be split anyway (docs/design.md "A mixed cell's vote stops early").
RegionCount region_vote(const std::vector<Vec3>& pts, uint64_t first_id, size_t batch,
                        const SurfaceIndex& surface, std::vector<uint32_t> triangles, double slab,
                        const BBox& oracle_box, const PointClassifier& classify, size_t& classified,
                        size_t mixed_at = 0);

// Sample points uniformly inside a live convex cell (deterministic for `seed`).
std::vector<Vec3> sample_cell(const CellComplex& cx, uint32_t cell, int count, uint64_t seed);

// Makes the union of `inside` 2-manifold: at an edge used by more than two boundary facets (two
// cells touching only along it), or at a vertex where two fans of boundary facets meet, a cell
// around it changes side (each cell at most once): the one whose flip puts the least of its vote
// on the wrong side (`share`: per cell id the inside share of its vote, CarveResult::inside_share;
// a cell without one counts as unanimous, so the smallest cell goes first).
// Returns the number of cells flipped; `flipped_volume` accumulates their volume.
size_t remove_pinch_edges(const CellComplex& cx, std::vector<uint32_t>& inside, double& flipped_volume,
                          const std::vector<float>& share = {});

// Lets the pinch repair cut a cell whose flip would cost more than `max_flip` (a wing of the
// building, a room of air) by the carving plane nearest the pinch that leaves it on one side,
// so that a piece along the pinch flips instead (docs/algorithm.md §8).
struct PinchCuts {
  const std::vector<CarvePlane>* planes = nullptr;
  const CarveParams* params = nullptr;
  BBox outer;  // the carving box
  double max_flip = 0;
};

// The same, cutting cells as `cuts` says; the pieces keep their cell's label and share (`share`
// grows with the new ids).
size_t remove_pinch_edges(CellComplex& cx, std::vector<uint32_t>& inside, double& flipped_volume,
                          std::vector<float>& share, const PinchCuts& cuts);

// Cells thinner than `width` (their smallest depth behind any of their facets) on the boundary of
// `inside` change side: a slab or wedge thinner than the output grid cannot be written (its faces
// fold onto each other when rounded; docs/algorithm.md §8). An outside cell that reaches the
// carving box stays outside. Returns the number of cells flipped; adds their volume.
size_t flip_thin_cells(const CellComplex& cx, std::vector<uint32_t>& inside, double width,
                       double& flipped_volume);

// Fills cavities: outside cells that cannot reach the carving box's boundary through other outside
// cells (voids enclosed by the building) become inside. Returns how many; adds their volume.
size_t fill_cavities(const CellComplex& cx, std::vector<uint32_t>& inside, double& filled_volume);

// Face-connected components of a set of cells (through facets with both sides in the set).
std::vector<std::vector<uint32_t>> connected_components(const CellComplex& cx,
                                                        const std::vector<uint32_t>& cells);

}  // namespace mc
