#include "core/level_passes.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "core/thread_tag.hpp"
#include "core/union_find.hpp"

namespace mc::level {

namespace {

// The analyses of the previous parts `qs` (indices into prev_cells) as single parts of the level's
// space, in parallel (they only read the complex); the others are left empty.
std::vector<PartAnalysis> analyze_whole(const LevelSpace& ls,
                                        const std::vector<std::vector<uint32_t>>& prev_cells,
                                        const std::vector<uint32_t>& qs, const AnalysisContext& ctx) {
  std::vector<PartAnalysis> info(prev_cells.size());
  tbb::parallel_for(size_t(0), qs.size(), with_thread_tag([&](size_t k) {
                      Bits whole(ls.space.words(), 0);
                      for (uint32_t c : prev_cells[qs[k]]) set_bit(whole, ls.local.at(c));
                      info[qs[k]] = analyze_part(ls.space, std::move(whole), ctx, kNoNewPlanes);
                    }));
  return info;
}

}  // namespace

// Undoes the cuts of a level that raise its whole-building cost (decompose.uncut_convexity).
// Each part is searched with its own normalisers (docs/algorithm.md §11.2), so a search can cut a
// nearly convex part into pieces that raise the level's cost (§11.1 with the normalisers of §11.3);
// the paper's own finest levels often cost more than a coarser one (its sample9: 1.8865 at 1e-2,
// 1.9231 at 1e-4; sample16: 1.6358 at 1e-3, 1.6510 at 1e-4).
// After the level's merges, the previous parts are grouped so that every part of the level lies
// within one group (a merge across a previous boundary joins the two groups). A group whose parts
// cost more than its previous parts whole is put back, costliest first, if every previous part is
// at least uncut_convexity convex and the level's volume-weighted convexity stays at least
// cvx_thresh: once the building is as convex as the user asks of a part, a further cut has to pay
// for itself in the objective. Coarse levels and visibly concave parts keep their cuts. Without
// the per-part floor, small, clearly concave parts would come back because the whole-building
// objective barely sees them (docs/algorithm.md §14.4, docs/design.md).
void refuse_costly_cuts(const Preprocessed& pre, const DecomposeParams& p, const std::vector<LevelPart>& prev,
                        std::vector<LevelPart>& work, const AnalysisContext& ctx, const Objective& obj) {
  const CellComplex& cx = *pre.complex;
  if (prev.empty()) return;
  std::unordered_map<uint32_t, uint32_t> prev_of;  // current cell -> previous part
  std::vector<std::vector<uint32_t>> prev_cells(prev.size());
  for (uint32_t q = 0; q < prev.size(); ++q) {
    prev_cells[q] = current_leaves(cx, prev[q].cells);
    for (uint32_t c : prev_cells[q]) prev_of[c] = q;
  }
  // Groups of previous parts (union-find, smallest index as root).
  UnionFind up(prev.size());
  auto find = [&](uint32_t q) { return up.find(q); };
  std::vector<uint32_t> first_owner(work.size());
  for (uint32_t j = 0; j < work.size(); ++j) {
    uint32_t r = CellComplex::kNone;
    for (uint32_t c : work[j].cells) {
      auto it = prev_of.find(c);
      if (it == prev_of.end()) return;  // a cell from no previous part: leave the level as it is
      const uint32_t o = find(it->second);
      if (r == CellComplex::kNone) r = o;
      else if (o != r) up.unite_low(o, r), r = std::min(o, r);
    }
    if (r == CellComplex::kNone) return;
    first_owner[j] = r;  // find() later gives the group's final root
  }
  std::map<uint32_t, std::vector<uint32_t>> parts_of, prevs_of;  // group root -> level parts / previous parts
  for (uint32_t j = 0; j < work.size(); ++j) parts_of[find(first_owner[j])].push_back(j);
  for (uint32_t q = 0; q < prev.size(); ++q) prevs_of[find(q)].push_back(q);
  if (std::none_of(parts_of.begin(), parts_of.end(), [](const auto& e) { return e.second.size() > 1; }))
    return;
  const LevelSpace ls(cx, work);
  std::vector<PartAnalysis> info;
  double weighted = 0, volume = 0;
  info = analyze_parts(ls.space, ls, work, ctx);
  for (const PartAnalysis& pi : info) {
    weighted += weighted_convexity(pi);
    volume += pi.volume;
  }
  // The previous parts of the groups that were cut, each analysed whole, then weighed group by
  // group in root order.
  std::vector<uint32_t> whole_parts;
  for (const auto& [g, js] : parts_of)
    if (js.size() > 1) whole_parts.insert(whole_parts.end(), prevs_of[g].begin(), prevs_of[g].end());
  const std::vector<PartAnalysis> whole_info = analyze_whole(ls, prev_cells, whole_parts, ctx);
  std::vector<std::tuple<double, uint32_t, double>> costly;  // (cost change, group, Σ V·convexity lost)
  for (const auto& [g, js] : parts_of) {
    const std::vector<uint32_t>& qs = prevs_of[g];
    if (js.size() <= 1) continue;  // a group that is one part is its one previous part
    double d_delta = 0, d_weighted = 0;
    int d_e = 0;
    bool stays_cut = false;  // a previous part would be pinched, or less convex than uncut_convexity
    for (uint32_t q : qs) {
      const PartAnalysis& qi = whole_info[q];
      stays_cut |= qi.pinch_edges > 0;
      stays_cut |= reported_convexity(qi) < p.uncut_convexity;
      d_delta -= qi.delta;
      d_e -= qi.e_all;
      d_weighted -= weighted_convexity(qi);
    }
    if (stays_cut) continue;
    for (uint32_t j : js) {
      d_delta += info[j].delta;
      d_e += info[j].e_all;
      d_weighted += weighted_convexity(info[j]);
    }
    const double dn = double(js.size()) - double(qs.size());
    const double change = obj.change(dn, d_delta, double(d_e));
    if (change > 1e-12) costly.emplace_back(change, g, d_weighted);
  }
  std::sort(costly.begin(), costly.end(), [](const auto& a, const auto& b) {
    return std::get<0>(a) != std::get<0>(b) ? std::get<0>(a) > std::get<0>(b)
                                            : std::get<1>(a) < std::get<1>(b);
  });
  std::vector<bool> restore(prev.size(), false);
  for (const auto& [change, g, lost] : costly) {
    if (volume <= 0 || (weighted - lost) / volume < p.cvx_thresh) continue;
    weighted -= lost;
    restore[g] = true;
  }
  // The level's parts in order; a restored group's previous parts take its first part's place.
  std::vector<LevelPart> next;
  std::set<uint32_t> done;
  for (uint32_t j = 0; j < work.size(); ++j) {
    const uint32_t g = find(first_owner[j]);
    if (!restore[g]) {
      next.push_back(std::move(work[j]));
    } else if (done.insert(g).second) {
      for (uint32_t q : prevs_of[g]) next.push_back({prev_cells[q], prev[q].component});
    }
  }
  work = std::move(next);
}

}  // namespace mc::level
