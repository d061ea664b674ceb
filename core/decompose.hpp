// MorphCut decomposition: the LoD driver over best-first branch-and-bound searches
// (docs/algorithm.md §9–§14).
//
// For each LoD level (coarse to fine) every current part is searched independently: first
// (sequentially) the part's cells are refined once by all of its candidate planes, so that
// every cut inside the search is combinatorial; then the searches of a level run in parallel
// (TBB), read-only on the shared complex. The level passes (§14) follow each level. The deadline
// is checked in the search and between levels: on expiry the best complete result so far is
// returned and marked partial.
#pragma once
#include <string>
#include <vector>

#include "core/params.hpp"
#include "core/polygon_mesh.hpp"
#include "core/preprocess.hpp"

namespace mc {

struct PartResult {
  std::vector<uint32_t> cells;  // global cells when recorded (expand with CellComplex::leaves)
  double volume = 0, hull_volume = 0;
  double convexity = 0;              // V / V_CH
  std::vector<uint32_t> neighbours;  // indices of parts of the same level sharing a face
  int component = 0;                 // singleton component the part belongs to
  bool operator==(const PartResult&) const = default;
};

struct LevelResult {
  double lod = 0;
  std::vector<PartResult> parts;
  double cost = 0, g = 0, h = 0;  // whole-building normalisation (docs/algorithm.md §11.3)
  double convexity = 0;           // volume-weighted mean of V/V_CH
  double min_convexity = 0;
  double mean_convexity = 0;  // unweighted mean (paper Eq. C.1)
  int remaining_concave = 0;  // Σ E_all over parts
  int64_t nodes_expanded = 0;
  double seconds = 0;
  bool truncated = false;  // a search hit the deadline or its node budget
};

struct Decomposition {
  std::vector<LevelResult> levels;
  bool partial = false;  // deadline reached: some level is not fully searched
  std::string reason;
  int concave_edges = 0;  // E_all of the singleton cell
  double seconds = 0;
};

Decomposition decompose(Preprocessed& pre, const DecomposeParams& p, Clock::time_point deadline);

// decompose() with the fidelity measure that preprocess() deferred (measure_fidelity()) running
// beside it: the levels leave threads idle between their parallel steps, and the measure fills
// them (docs/design.md, "Fidelity beside the levels").
Decomposition decompose_measuring_fidelity(Preprocessed& pre, const DecomposeParams& p,
                                           Clock::time_point deadline);

// The closed surface of one part in input coordinates: coplanar faces merged, cut faces labelled
// "ClosureSurface", others with the label of the input plane they lie on.
PolygonMesh part_mesh(const Preprocessed& pre, const PartResult& part);
// Every part of one level, written to fit its neighbours exactly (docs/output-format.md §Validity):
// a face shared by two parts is the same polygon in both (Polygon::neighbour names the other
// part), and every corner of any part's face is a vertex of each ring passing through it.
std::vector<PolygonMesh> level_part_meshes(const Preprocessed& pre, const std::vector<PartResult>& parts);
// The singleton cell (all components) as a mesh in input coordinates.
PolygonMesh singleton_mesh(const Preprocessed& pre);

}  // namespace mc
