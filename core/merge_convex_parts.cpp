#include "core/level_passes.hpp"
#include "core/thread_tag.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace mc::level {

// Merges neighbouring parts while that lowers the level's cost (docs/algorithm.md §14.3, with the
// whole-building normalisers of §11.3). The search is inflated (σ > 1), keeps only the best
// children and cuts whole parts by unbounded planes, so it often leaves two convex pieces whose
// union is still convex (a cut that also went through an unrelated wing), or nearly so. Merging
// such a pair removes a part at no loss of convexity; a merge is only taken if the union has no
// concave line significant at this level (the level would cut it again) and stays 2-manifold.
// Greedy, best decrease first; ties by part index (deterministic).
void merge_convex_neighbours(const Preprocessed& pre, std::vector<LevelPart>& work,
                             const AnalysisContext& ctx, const Objective& obj) {
  const CellComplex& cx = *pre.complex;
  if (work.size() < 2) return;
  const LevelSpace ls(cx, work);
  const CellSpace& space = ls.space;
  const auto& local = ls.local;
  // Cost change of replacing parts a and b by their union u (|P| drops by one).
  auto gain = [&](const PartAnalysis& a, const PartAnalysis& b, const PartAnalysis& u) {
    return obj.change(-1.0, u.delta - a.delta - b.delta, u.e_all - a.e_all - b.e_all);
  };
  std::vector<PartAnalysis> info = analyze_parts(space, ls, work, ctx);
  std::vector<bool> alive(work.size(), true);
  std::vector<uint32_t> owner(space.cells.size());
  auto neighbours = [&](uint32_t i) {
    return neighbour_owners(cx, work[i].cells, i, [&](uint32_t c) {
      auto it = local.find(c);
      return it == local.end() ? CellComplex::kNone : owner[it->second];
    });
  };
  for (uint32_t i = 0; i < work.size(); ++i)
    for (uint32_t c : work[i].cells) owner[local.at(c)] = i;
  // Candidate merges, evaluated lazily and cached until one of the two parts changes.
  std::map<std::pair<uint32_t, uint32_t>, std::optional<std::pair<double, PartAnalysis>>> cache;
  auto evaluate = [&](uint32_t a, uint32_t b) -> const std::optional<std::pair<double, PartAnalysis>>& {
    auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    std::optional<std::pair<double, PartAnalysis>> r;
    Bits u = info[a].bits;
    for (size_t w = 0; w < u.size(); ++w) u[w] |= info[b].bits[w];
    PartAnalysis ui = analyze_part(space, std::move(u), ctx, kNoNewPlanes);
    const double g = gain(info[a], info[b], ui);
    if (ui.e_sig == 0 && ui.pinch_edges == 0 && g < -1e-9) r.emplace(g, std::move(ui));
    return cache.emplace(key, std::move(r)).first->second;
  };
  for (size_t guard = 0; guard < work.size(); ++guard) {
    // The unions not yet evaluated, analysed in parallel (evaluate() is then a cache hit).
    std::vector<std::pair<uint32_t, uint32_t>> todo;
    for (uint32_t a = 0; a < work.size(); ++a) {
      if (!alive[a]) continue;
      for (uint32_t b : neighbours(a))
        if (b > a && alive[b] && work[a].component == work[b].component && !cache.count({a, b}))
          todo.emplace_back(a, b);
    }
    std::vector<PartAnalysis> unions(todo.size());
    tbb::parallel_for(size_t(0), todo.size(), with_thread_tag([&](size_t i) {
                        Bits u = info[todo[i].first].bits;
                        for (size_t w = 0; w < u.size(); ++w) u[w] |= info[todo[i].second].bits[w];
                        unions[i] = analyze_part(space, std::move(u), ctx, kNoNewPlanes);
                      }));
    for (size_t i = 0; i < todo.size(); ++i) {
      const auto [a, b] = todo[i];
      std::optional<std::pair<double, PartAnalysis>> r;
      const double g = gain(info[a], info[b], unions[i]);
      if (unions[i].e_sig == 0 && unions[i].pinch_edges == 0 && g < -1e-9) r.emplace(g, std::move(unions[i]));
      cache.emplace(std::make_pair(a, b), std::move(r));
    }
    double best = 0;
    std::pair<uint32_t, uint32_t> pick{0, 0};
    for (uint32_t a = 0; a < work.size(); ++a) {
      if (!alive[a]) continue;
      for (uint32_t b : neighbours(a)) {
        if (b <= a || !alive[b] || work[a].component != work[b].component) continue;
        const auto& r = evaluate(a, b);
        if (r && r->first < best - 1e-12) {
          best = r->first;
          pick = {a, b};
        }
      }
    }
    if (best == 0) break;
    const auto [a, b] = pick;
    PartAnalysis merged = cache[{a, b}]->second;
    work[a].cells.insert(work[a].cells.end(), work[b].cells.begin(), work[b].cells.end());
    std::sort(work[a].cells.begin(), work[a].cells.end());
    for (uint32_t c : work[b].cells) owner[local.at(c)] = a;
    work[b].cells.clear();
    alive[b] = false;
    info[a] = std::move(merged);
    for (auto it = cache.begin(); it != cache.end();)
      it = (it->first.first == a || it->first.second == a || it->first.first == b || it->first.second == b)
               ? cache.erase(it)
               : std::next(it);
  }
  std::vector<LevelPart> kept;
  for (uint32_t i = 0; i < work.size(); ++i)
    if (alive[i]) kept.push_back(std::move(work[i]));
  work = std::move(kept);
}

}  // namespace mc::level
