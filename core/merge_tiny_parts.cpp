#include "core/level_passes.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>

#include "core/hull.hpp"
#include "core/thread_tag.hpp"

namespace mc::level {

namespace {

double volume_of(const CellComplex& cx, const std::vector<uint32_t>& cells) {
  double v = 0;
  for (uint32_t c : cells) v += cx.cell_volume(c);
  return v;
}

// The cells' distinct vertex ids, ascending (cells share them).
std::vector<uint32_t> vertices_of(const CellComplex& cx, const std::vector<uint32_t>& cells) {
  std::vector<uint32_t> ids;
  for (uint32_t c : cells)
    for (uint32_t v : cx.cell_vertices(c)) ids.push_back(v);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

std::vector<uint32_t> united(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
  std::vector<uint32_t> ids;
  ids.reserve(a.size() + b.size());
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(ids));
  return ids;
}

// The volume of the hull of the vertices `ids`.
double hull_volume(const CellComplex& cx, const std::vector<uint32_t>& ids, HullCache* hulls) {
  std::vector<Vec3> pts;
  pts.reserve(ids.size());
  for (uint32_t v : ids) pts.push_back(cx.point(v));
  return hulls ? hulls->get(pts)->volume : convex_hull(pts).volume;
}

}  // namespace

// Merges parts smaller than v_min into a neighbour (docs/algorithm.md §14.2), smallest first;
// parts without a neighbour they can join stay.
void merge_tiny_parts(const CellComplex& cx, std::vector<LevelPart>& parts, double v_min, HullCache* hulls) {
  // Each part's volume (summed in its cell order) and distinct vertex ids, kept across the merges:
  // a merge changes only its target, whose values are then what a fresh pass would compute.
  std::vector<double> vol;
  std::vector<std::vector<uint32_t>> verts;
  for (const LevelPart& p : parts) {
    vol.push_back(volume_of(cx, p.cells));
    verts.push_back(vertices_of(cx, p.cells));
  }
  constexpr uint32_t kNoPart = ~0u;
  std::vector<uint32_t> owner(cx.num_cells(), kNoPart);
  for (int guard = 0; guard < 10000; ++guard) {
    std::fill(owner.begin(), owner.end(), kNoPart);
    for (uint32_t i = 0; i < parts.size(); ++i)
      for (uint32_t c : parts[i].cells) owner[c] = i;
    int victim = -1;
    for (uint32_t i = 0; i < parts.size(); ++i)
      if (vol[i] < v_min && (victim < 0 || vol[i] < vol[victim])) victim = static_cast<int>(i);
    if (victim < 0) return;
    std::map<uint32_t, double> shared;
    for (uint32_t c : parts[victim].cells)
      for (uint32_t f : cx.cell(c).facets) {
        const uint32_t o = cx.other_side(f, c);
        const uint32_t w = o == CellComplex::kNone ? kNoPart : owner[o];
        if (w != kNoPart && w != static_cast<uint32_t>(victim)) shared[w] += cx.facet_area(f);
      }
    if (shared.empty()) {
      v_min = std::min(v_min, vol[victim]);  // isolated: keep it, look at larger ones only
      continue;
    }
    // Among the neighbours whose union with the victim stays 2-manifold, the one whose convex
    // hull grows least; then the largest shared area (the research code's rule). A sliver can be
    // long: merged into the neighbour it shares most area with, it can take a convex box's
    // convexity far down (docs/design.md, "Tiny parts merge where the hull grows least").
    const double tol = 1e-9 * std::max(1.0, v_min);
    // Each neighbour's union evaluated in parallel (they only read the complex), then chosen in
    // neighbour order as one after the other would.
    const std::vector<std::pair<uint32_t, double>> options(shared.begin(), shared.end());
    std::vector<std::optional<double>> growths(options.size());  // none: the union pinches
    tbb::parallel_for(size_t(0), options.size(), with_thread_tag([&](size_t i) {
                        const uint32_t p = options[i].first;
                        std::vector<uint32_t> merged = parts[p].cells;
                        merged.insert(merged.end(), parts[victim].cells.begin(), parts[victim].cells.end());
                        if (!has_pinch_edge(cx, merged))
                          growths[i] = hull_volume(cx, united(verts[p], verts[victim]), hulls) -
                                       hull_volume(cx, verts[p], hulls) - vol[victim];
                      }));
    int target = -1;
    double best_growth = 0, best_area = 0;
    for (size_t i = 0; i < options.size(); ++i) {
      const auto [p, area] = options[i];
      if (!growths[i]) continue;
      const double growth = *growths[i];
      if (target < 0 || growth < best_growth - tol || (growth <= best_growth + tol && area > best_area)) {
        target = static_cast<int>(p);
        best_growth = growth;
        best_area = area;
      }
    }
    if (target < 0) {
      v_min = std::min(v_min, vol[victim]);  // no valid merge: keep it
      continue;
    }
    auto& dst = parts[target].cells;
    dst.insert(dst.end(), parts[victim].cells.begin(), parts[victim].cells.end());
    std::sort(dst.begin(), dst.end());
    vol[target] = volume_of(cx, dst);
    verts[target] = united(verts[target], verts[victim]);
    parts.erase(parts.begin() + victim);
    vol.erase(vol.begin() + victim);
    verts.erase(verts.begin() + victim);
  }
}

}  // namespace mc::level
