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

#include "core/search.hpp"

namespace mc::level {

namespace {

// The previous level's parts and this level's pieces, and how they relate.
struct Boundaries {
  std::unordered_map<uint32_t, uint32_t> prev_of, work_of;  // leaf cell -> previous part, piece
  std::vector<int64_t> home;                   // the previous part a piece lies in (-1: it straddles two)
  std::vector<std::vector<uint32_t>> pieces;   // the pieces of each previous part
  std::vector<bool> clean;                     // every cell of the previous part is in its pieces
  std::vector<std::vector<uint32_t>> touches;  // pieces sharing a facet with each piece
};

// A union of pieces along one boundary, searched again.
struct Candidate {
  int component = 0;
  std::vector<uint32_t> old_pieces;
  double old_delta = 0, old_e = 0;
  int old_sig = 0;
  PreparedPart pr;
  SearchResult sr;
};

// Step 1: which pieces lie in which previous part. A previous part whose cells are not all in
// clean pieces (a merge crossed it) is left alone.
Boundaries relate_pieces(const CellComplex& cx, const std::vector<LevelPart>& prev,
                         const std::vector<LevelPart>& work) {
  Boundaries bd;
  for (uint32_t i = 0; i < prev.size(); ++i)
    for (uint32_t c : prev[i].cells) bd.prev_of[c] = i;
  for (uint32_t i = 0; i < work.size(); ++i)
    for (uint32_t c : work[i].cells) bd.work_of[c] = i;
  bd.home.assign(work.size(), -1);
  bd.pieces.resize(prev.size());
  for (uint32_t w = 0; w < work.size(); ++w) {
    auto it = bd.prev_of.find(work[w].cells.front());
    if (it == bd.prev_of.end()) continue;
    const uint32_t h = it->second;
    bool inside = true;
    for (uint32_t c : work[w].cells) {
      auto jt = bd.prev_of.find(c);
      inside &= jt != bd.prev_of.end() && jt->second == h;
    }
    if (inside) {
      bd.home[w] = h;
      bd.pieces[h].push_back(w);
    }
  }
  bd.clean.resize(prev.size());
  for (uint32_t i = 0; i < prev.size(); ++i) {
    size_t covered = 0;
    for (uint32_t w : bd.pieces[i]) covered += work[w].cells.size();
    bd.clean[i] = covered == prev[i].cells.size();
  }
  bd.touches.resize(work.size());
  for (uint32_t w = 0; w < work.size(); ++w)
    bd.touches[w] = neighbour_owners(cx, work[w].cells, w, lookup_in(bd.work_of));
  return bd;
}

// Only the pieces along the boundary of a and b are searched again: that boundary is what a
// joint search can move, and the union stays small. Empty unless three or more, connected.
std::vector<uint32_t> border_of(const Boundaries& bd, uint32_t a, uint32_t b) {
  std::vector<uint32_t> border;
  for (const auto& side : {std::make_pair(a, b), std::make_pair(b, a)}) {
    const int64_t other = side.second;  // (clang cannot capture a structured binding)
    for (uint32_t w : bd.pieces[side.first])
      if (std::any_of(bd.touches[w].begin(), bd.touches[w].end(),
                      [&](uint32_t t) { return bd.home[t] == other; }))
        border.push_back(w);
  }
  if (border.size() < 3) return {};
  std::set<uint32_t> seen{border.front()};
  std::vector<uint32_t> stack{border.front()};
  while (!stack.empty()) {
    const uint32_t w = stack.back();
    stack.pop_back();
    for (uint32_t t : bd.touches[w])
      if (std::find(border.begin(), border.end(), t) != border.end() && seen.insert(t).second)
        stack.push_back(t);
  }
  return seen.size() == border.size() ? border : std::vector<uint32_t>{};
}

// Step 2: every border of two neighbouring clean previous parts, prepared and searched as one
// part. Searched at once: a later union's refinement may split these cells, and their facets then
// face the children (a search on them would see wrong orientations). Its parts stay valid as
// regions (read back through the current leaves).
std::vector<Candidate> search_borders(Preprocessed& pre, const std::vector<LevelPart>& prev,
                                      const std::vector<LevelPart>& work, const Boundaries& bd,
                                      const AnalysisContext& ctx, const AnalysisContext& rctx,
                                      Clock::time_point deadline) {
  CellComplex& cx = *pre.complex;
  // The pieces' share of the level's cost, analysed once each, when a union first needs it.
  std::vector<std::optional<PartAnalysis>> piece_info(work.size());
  auto info_of = [&](uint32_t w) -> const PartAnalysis& {
    if (!piece_info[w]) {
      const CellSpace space = make_space(cx, current_leaves(cx, work[w].cells));
      piece_info[w] = analyze_part(space, space.all(), ctx, kNoNewPlanes);
    }
    return *piece_info[w];
  };
  std::vector<Candidate> cands;
  for (uint32_t a = 0; a < prev.size() && Clock::now() <= deadline; ++a)
    for (uint32_t b : neighbour_owners(cx, prev[a].cells, a, lookup_in(bd.prev_of))) {
      if (b < a || prev[b].component != prev[a].component || !bd.clean[a] || !bd.clean[b]) continue;
      const std::vector<uint32_t> border = border_of(bd, a, b);
      if (border.empty()) continue;
      Candidate cd;
      cd.component = prev[a].component;
      cd.old_pieces = border;
      LevelPart u{{}, cd.component};
      for (uint32_t w : border) {
        const PartAnalysis& info = info_of(w);
        cd.old_delta += info.delta;
        cd.old_e += info.e_all;
        cd.old_sig += info.e_sig;
        // Earlier candidates' refinement may have split cells: work on the current leaves.
        const std::vector<uint32_t> leaves = current_leaves(cx, work[w].cells);
        u.cells.insert(u.cells.end(), leaves.begin(), leaves.end());
      }
      std::sort(u.cells.begin(), u.cells.end());
      cd.pr = prepare(pre, u, rctx);
      if (!cd.pr.search) continue;
      cd.pr.input.deadline = deadline;
      cd.pr.input.space = &cd.pr.space;
      cd.sr = search(cd.pr.input, cd.pr.root);
      cd.pr.input.positive.clear();
      cands.push_back(std::move(cd));
    }
  return cands;
}

// Step 3: the unions that lower the level's cost with no more parts and no more significant
// concave lines, by decreasing gain (ties by their order).
std::vector<std::pair<double, size_t>> gains_of(const std::vector<Candidate>& cands, const Objective& obj,
                                                LevelResult& level) {
  std::vector<std::pair<double, size_t>> gains;
  for (size_t i = 0; i < cands.size(); ++i) {
    const Candidate& cd = cands[i];
    level.nodes_expanded += cd.sr.expanded;
    if (cd.sr.deadline_hit || cd.sr.parts.empty() || cd.sr.parts.size() > cd.old_pieces.size()) continue;
    double sum_delta = 0, sum_e = 0;
    int sum_sig = 0;
    for (const PartAnalysis& part : cd.sr.parts) {
      sum_delta += part.delta;
      sum_e += part.e_all;
      sum_sig += part.e_sig;
    }
    // Never trade significant concave lines for fewer parts (a root the search could not cut).
    if (sum_sig > cd.old_sig) continue;
    const double dn = static_cast<double>(cd.sr.parts.size()) - static_cast<double>(cd.old_pieces.size());
    const double gain = obj.change(dn, sum_delta - cd.old_delta, sum_e - cd.old_e);
    if (gain < -1e-9) gains.emplace_back(gain, i);
  }
  std::sort(gains.begin(), gains.end());
  return gains;
}

// Step 4: the unions taken greedily over disjoint piece sets replace their pieces.
void replace_pieces(const CellComplex& cx, const std::vector<Candidate>& cands,
                    const std::vector<std::pair<double, size_t>>& gains, std::vector<LevelPart>& work) {
  std::vector<bool> removed(work.size(), false);
  std::vector<LevelPart> added;
  for (const auto& [gain, i] : gains) {
    const Candidate& cd = cands[i];
    if (std::any_of(cd.old_pieces.begin(), cd.old_pieces.end(), [&](uint32_t w) { return removed[w]; }))
      continue;
    for (uint32_t w : cd.old_pieces) removed[w] = true;
    for (const PartAnalysis& part : cd.sr.parts) {
      LevelPart nw{{}, cd.component};
      for (uint32_t k = 0; k < cd.pr.space.cells.size(); ++k)
        if (test_bit(part.bits, k)) nw.cells.push_back(cd.pr.space.cells[k]);
      added.push_back(std::move(nw));
    }
  }
  for (LevelPart& w : work) w.cells = current_leaves(cx, w.cells);
  for (LevelPart& w : added) w.cells = current_leaves(cx, w.cells);
  if (added.empty()) return;
  std::vector<LevelPart> next;
  for (uint32_t w = 0; w < work.size(); ++w)
    if (!removed[w]) next.push_back(std::move(work[w]));
  for (LevelPart& w : added) next.push_back(std::move(w));
  work = std::move(next);
}

}  // namespace

// Re-searches the boundary between neighbouring parts of the previous level (opt-in,
// decompose.revisit_boundaries). Each part of a level is refined on its own, so a boundary chosen
// at a coarser level is final: a rooftop unit cut there into its upper box and an L-shaped rest
// needs two pieces for the rest, where one different cut gives two convex parts for the whole
// unit (sample11: 16 parts -> 13). For every pair of neighbouring previous parts, the pieces of
// this level along their common boundary (three or more, connected) are searched again as one
// part with the `revisit_candidates` heaviest candidate planes; the result replaces them when it
// has no more parts, no more significant concave lines, and lowers the level's cost (with the
// whole-building normalisers, docs/algorithm.md §11.3, as in merge_convex_neighbours). Each
// union is searched right after its preparation; then the results are taken greedily by
// decrease over disjoint piece sets, ties by pair order, so the outcome does not depend on the
// thread count.
// Cost: preparing each union (refining its cells by its candidates) and its search, and the
// refinement of a rejected union stays in the complex. 3-piece unions are most of the work and
// few are improved, so the gain in parts is small for its time (docs/algorithm.md §14.1,
// docs/design.md). Hence off by default.
void revisit_boundaries(Preprocessed& pre, const DecomposeParams& p, std::vector<LevelPart> prev,
                        std::vector<LevelPart>& work, const AnalysisContext& ctx, const Objective& obj,
                        Clock::time_point deadline, LevelResult& level) {
  CellComplex& cx = *pre.complex;
  if (prev.size() < 2 || work.size() < 3) return;
  DecomposeParams rp = p;
  rp.max_candidates = p.revisit_candidates;
  AnalysisContext rctx = ctx;
  rctx.dec = &rp;
  for (LevelPart& w : prev) w.cells = current_leaves(cx, w.cells);
  for (LevelPart& w : work) w.cells = current_leaves(cx, w.cells);
  const Boundaries bd = relate_pieces(cx, prev, work);
  const std::vector<Candidate> cands = search_borders(pre, prev, work, bd, ctx, rctx, deadline);
  replace_pieces(cx, cands, gains_of(cands, obj, level), work);
}

}  // namespace mc::level
