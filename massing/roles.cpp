#include "massing/roles.hpp"

#include <algorithm>
#include <numeric>

namespace mc::massing {

void assign_roles(LevelMassing& L, const MassingParams& p) {
  auto& M = L.masses;
  const size_t n = M.size();
  for (auto& m : M) m.role.clear();
  std::vector<size_t> by_volume(n);
  std::iota(by_volume.begin(), by_volume.end(), size_t{0});
  std::stable_sort(by_volume.begin(), by_volume.end(),
                   [&](size_t a, size_t b) { return M[a].volume > M[b].volume; });
  auto height = [&](size_t i) { return M[i].z_max - M[i].z_min; };

  // 1. podium and tower: a raised mass t stacked on the largest grounded mass q, covering a small
  //    share of q's footprint, taller than its plan is long (a long slab storey is a setback), at
  //    least as tall as q, and not a rooftop unit by volume.
  size_t largest_grounded = n;
  for (size_t i : by_volume)
    if (M[i].grounded) {
      largest_grounded = i;
      break;
    }
  for (size_t t : by_volume) {
    if (M[t].grounded || !M[t].role.empty()) continue;
    for (const Contact& c : M[t].contacts) {
      if (c.kind != "stacked" || c.above != 1) continue;
      const size_t q = c.other;
      if (q != largest_grounded) continue;
      if (M[t].volume <= p.rooftop_max_share * M[q].volume) continue;
      if (c.area > p.podium_max_roof_share * M[q].footprint_area) continue;
      if (height(t) < p.tower_min_slenderness * M[t].length) continue;
      if (height(t) < p.tower_min_height_ratio * height(q)) continue;
      M[q].role = "podium";
      M[t].role = "tower";
      break;
    }
  }
  // 2. main: the largest grounded mass left.
  size_t main = n;
  for (size_t i : by_volume)
    if (M[i].grounded && M[i].role.empty()) {
      main = i;
      M[i].role = "main";
      break;
    }
  double reference = main < n ? M[main].volume : 0;
  if (main == n)
    for (size_t i : by_volume)
      if (M[i].role == "podium") {
        reference = M[i].volume;
        break;
      }
  // 3./4. the other grounded masses: wing when substantial, else annex.
  for (size_t i = 0; i < n; ++i)
    if (M[i].grounded && M[i].role.empty())
      M[i].role = M[i].volume >= p.wing_min_share * reference ? "wing" : "annex";
  // 5./6. other raised masses: rooftop when small beside what carries them, else setback.
  for (size_t i = 0; i < n; ++i) {
    if (!M[i].role.empty()) continue;
    // Support: the mass it rests on with the largest shared area (stacked or inclined contact,
    // this mass above); else the mass it shares most with; else the largest mass.
    long s = -1;
    double best = -1;
    for (const Contact& c : M[i].contacts)
      if (c.above == 1 && c.area > best) best = c.area, s = static_cast<long>(c.other);
    if (s < 0)
      for (const Contact& c : M[i].contacts)
        if (c.area > best) best = c.area, s = static_cast<long>(c.other);
    const double support = s >= 0 ? M[static_cast<size_t>(s)].volume : (n ? M[by_volume[0]].volume : 0);
    M[i].role = M[i].volume <= p.rooftop_max_share * support ? "rooftop" : "setback";
  }
  for (auto& pm : L.parts) pm.role = pm.mass >= 0 ? M[static_cast<size_t>(pm.mass)].role : "";
}

}  // namespace mc::massing
