// Fidelity measure between two surfaces (docs/algorithm.md §8: input ↔ singleton cell), on
// triangle soups: open, non-manifold and self-intersecting inputs are fine.
#pragma once
#include "core/soup.hpp"

namespace mc {

struct HausdorffResult {
  double a_to_b = 0;  // max over points of a of the distance to b
  double b_to_a = 0;
  double symmetric = 0;    // max of the two
  double mean_a_to_b = 0;  // area-weighted mean distance from a to b
  double mean_b_to_a = 0;
  double mean_symmetric = 0;  // mean of the two one-sided means (mean surface deviation)
};

// Points are sampled on every triangle (deterministic barycentric lattice with spacing <=
// `sampling_step`, slivers first bisected into fat pieces) and their exact closest-point
// distances to the other soup are taken (an Embree BVH finds the candidates, the distances are exact in
// doubles). The maxima are lower bounds within `sampling_step` of the true values. The lattice holds at
// most 8000 samples per side (coarser when needed; corners and edges always sampled), from which the
// means are estimated. A step <= 0 means 0.1% of the bounding-box diagonal. Degenerate triangles are ignored.
// An empty side: distances from it are 0, to it +infinity. Works on open, non-manifold, self-intersecting
// soups. `means` false: the means are left 0 and only the maxima are measured, from the same lattice but
// skipping the triangles whose corners bound their distances below the maximum (the same maxima, bit for bit,
// at a fraction of the queries).
HausdorffResult hausdorff(const TriangleSoup& a, const TriangleSoup& b, double sampling_step,
                          bool means = true);

}  // namespace mc
