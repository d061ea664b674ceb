// Fidelity measure between two surfaces (architecture.md §3: input ↔ singleton cell), on
// triangle soups: open, non-manifold and self-intersecting inputs are fine.
#pragma once
#include "core/soup.hpp"

namespace mc {

struct HausdorffResult {
  double a_to_b = 0;       // max over points of a of the distance to b
  double b_to_a = 0;
  double symmetric = 0;    // max of the two
  double mean_a_to_b = 0;  // area-weighted mean distance from a to b
};

// Points are sampled on every triangle of each soup on a barycentric lattice whose spacing is
// at most `sampling_step` (vertices and edges included; deterministic), and their exact
// closest-point distances to the other soup are taken (CGAL AABB tree). So the result is a
// lower bound of the true distance that is within `sampling_step` of it. The lattice is
// coarsened if a side would need more than 4·10^6 points; a step <= 0 means 0.1% of the
// bounding-box diagonal. Degenerate triangles are ignored.
// An empty side: distances from it are 0, distances to it are +infinity.
HausdorffResult hausdorff(const TriangleSoup& a, const TriangleSoup& b, double sampling_step);

}  // namespace mc
