// The objective f = g + σ·h of a decomposition (paper Eq. 3, 5, 6; docs/algorithm.md §11), in one
// place: the search's node costs, a part's share of them, and the level passes' cost changes.
#pragma once
#include <cstddef>

#include "core/params.hpp"

namespace mc {

struct Objective {
  double n_max = 1;   // N_max = E_all(root) + 1
  double delta0 = 1;  // Δ(root) = ΔCH of the root (1 when the root is convex)
  double sigma = 2, k = 4;

  // The normalisers of a root with `e_all` concave lines and hull gap `delta`.
  static Objective of_root(int e_all, double delta, const DecomposeParams& p) {
    Objective o;
    o.n_max = e_all + 1;
    o.delta0 = delta > 0 ? delta : 1.0;
    o.sigma = p.sigma;
    o.k = p.k;
    return o;
  }
  double g(size_t parts, double sum_delta) const { return parts / n_max + (delta0 - sum_delta) / delta0; }
  double h(double sum_e, double sum_delta) const { return sum_e / (k * n_max) + sum_delta / delta0; }
  // f = g + σh.
  double cost(double g_value, double h_value) const { return g_value + sigma * h_value; }
  // One part's share of g + σh (the cost is a sum over parts plus a constant).
  double part_cost(double delta, double e_all) const {
    return 1.0 / n_max - delta / delta0 + sigma * (e_all / (k * n_max) + delta / delta0);
  }
  // The change of g + σh when the part count, ΣΔ and ΣE_all change by dn, d_delta and d_e.
  double change(double dn, double d_delta, double d_e) const {
    return dn / n_max + (sigma - 1.0) * d_delta / delta0 + sigma * d_e / (k * n_max);
  }
};

}  // namespace mc
