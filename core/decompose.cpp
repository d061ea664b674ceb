#include "core/decompose.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "core/hull.hpp"
#include "core/search.hpp"
#include "core/surface.hpp"
#include "core/union_find.hpp"

namespace mc {

namespace {

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::vector<uint32_t> current_leaves(const CellComplex& cx, const std::vector<uint32_t>& cells) {
  std::vector<uint32_t> out;
  for (uint32_t c : cells) cx.leaves(c, out);
  std::sort(out.begin(), out.end());
  return out;
}

// One part of a level being worked on.
struct Work {
  std::vector<uint32_t> cells;  // live cells
  int component = 0;
};

// The owners other than `self` of the cells across the facets of `cells`, ascending; `owner_of`
// maps a cell to its owner, or to CellComplex::kNone for a cell outside every part.
template <class OwnerOf>
std::vector<uint32_t> neighbour_owners(const CellComplex& cx, const std::vector<uint32_t>& cells, uint32_t self,
                                       const OwnerOf& owner_of) {
  std::vector<uint32_t> nb;
  for (uint32_t c : cells)
    for (uint32_t f : cx.cell(c).facets) {
      const uint32_t o = cx.other_side(f, c);
      const uint32_t w = o == CellComplex::kNone ? CellComplex::kNone : owner_of(o);
      if (w != CellComplex::kNone && w != self) nb.push_back(w);
    }
  std::sort(nb.begin(), nb.end());
  nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  return nb;
}

// Owner lookup in a cell -> owner map.
auto lookup_in(const std::unordered_map<uint32_t, uint32_t>& m) {
  return [&m](uint32_t c) {
    auto it = m.find(c);
    return it == m.end() ? CellComplex::kNone : it->second;
  };
}

// A part searched at this level: its refined space and search inputs.
struct Prepared {
  CellSpace space;
  SearchInput input;
  PartInfo root;
  bool search = false;
};

AnalysisContext make_context(const Preprocessed& pre, const DecomposeParams& p, double level) {
  AnalysisContext ctx;
  ctx.dec = &p;
  ctx.dist = pre.dist;
  ctx.angle_rad = pre.angle_rad;
  const Vec3 ext = pre.box.hi - pre.box.lo;
  ctx.a_diag = std::max(ext.z * std::sqrt(ext.x * ext.x + ext.y * ext.y), 1e-12);
  ctx.level = level;
  ctx.box = pre.box;
  return ctx;
}

// Sequential phase: analyse the part, register its candidate planes, refine its cells by them,
// and precompute on which side of every candidate each refined cell lies (exact predicates).
// Refines a part's cells by its candidate planes (the only step of a part's preparation that
// changes the complex). `finish` builds the part's space and root analysis afterwards: refining
// a neighbouring part splits the facets the two share, so a space built before that would keep
// dead facets (stale loops: boundary edges used once, false pinched vertices that refuse every
// cut). Hence all parts of a level are refined first, then all spaces are built.
Prepared refine(Preprocessed& pre, const Work& w, const AnalysisContext& ctx) {
  CellComplex& cx = *pre.complex;
  PlaneRegistry& reg = *pre.planes;
  Prepared pr;
  CellSpace coarse = make_space(cx, w.cells);
  const PlaneResolver add = [&](const Plane& g, const std::vector<uint32_t>& pool) -> std::optional<uint32_t> {
    return reg.add_snapped(g, pool, ctx.angle_rad, ctx.dist, ctx.box, PlaneOrigin::Candidate);
  };
  PartInfo info = analyze_part(coarse, coarse.all(), ctx, add);
  if (info.e_sig == 0 || info.candidates.empty()) {
    pr.space = std::move(coarse);
    pr.root = std::move(info);
    return pr;
  }
  std::vector<uint32_t> cells = w.cells;
  // A candidate passing a hair (δ/10) from a cell vertex without going through it would make
  // vertices that collapse when the output is quantised (invalid solids): that cell is left
  // whole, and a cut along the plane follows the cell's boundary there instead (the parts stay
  // unions of cells, hence closed). Same rule as in carving.
  const double hair = 0.1 * ctx.dist;
  auto hair_close = [&](uint32_t c, uint32_t plane) {
    const Plane& pl = reg[plane];
    for (uint32_t v : cx.cell_vertices(c)) {
      const double s = std::abs(pl.signed_distance(cx.point(v)));
      if (s < hair && cx.vertex_side(v, plane) != 0) return true;
    }
    return false;
  };
  for (uint32_t plane : info.candidates) {
    std::vector<uint32_t> next;
    for (uint32_t c : cells) {
      if (hair_close(c, plane)) {
        next.push_back(c);
        continue;
      }
      if (auto r = cx.split(c, plane)) {
        next.push_back(r->neg);
        next.push_back(r->pos);
      } else {
        next.push_back(c);
      }
    }
    cells = std::move(next);
  }
  std::sort(cells.begin(), cells.end());
  pr.space.cells = std::move(cells);
  pr.input.pool = std::move(info.candidates);
  pr.search = true;  // until finish() decides
  return pr;
}

// The refined space and the cells on each candidate's positive side (exact predicates: one
// thread per complex).
void finish_space(const Preprocessed& pre, Prepared& pr, const AnalysisContext& ctx) {
  if (!pr.search) return;
  const CellComplex& cx = *pre.complex;
  pr.space = make_space(cx, std::vector<uint32_t>(pr.space.cells));
  const std::vector<uint32_t>& cells = pr.space.cells;
  for (uint32_t plane : pr.input.pool) {
    Bits pos(pr.space.words(), 0);
    for (uint32_t i = 0; i < cells.size(); ++i)
      if (cx.cell_side(cells[i], plane) > 0) set_bit(pos, i);
    pr.input.positive.push_back(std::move(pos));
  }
  pr.input.ctx = ctx;
}

// The search's root: the refined space analysed (reads only; several at once are fine).
void finish_root(const Preprocessed& pre, Prepared& pr, const AnalysisContext& ctx) {
  if (!pr.search) return;
  const PlaneRegistry& reg = *pre.planes;
  const auto& pool = pr.input.pool;
  const PlaneResolver lookup = [&](const Plane& g, const std::vector<uint32_t>&) -> std::optional<uint32_t> {
    for (uint32_t id : pool)
      if (same_plane_in_box(g, reg[id], ctx.angle_rad, ctx.dist, ctx.box)) return id;
    return std::nullopt;
  };
  pr.root = analyze_part(pr.space, pr.space.all(), ctx, lookup);
  pr.search = pr.root.e_sig > 0 && !pr.root.candidates.empty();
}

void finish(const Preprocessed& pre, Prepared& pr, const AnalysisContext& ctx) {
  finish_space(pre, pr, ctx);
  finish_root(pre, pr, ctx);
}

Prepared prepare(Preprocessed& pre, const Work& w, const AnalysisContext& ctx) {
  Prepared pr = refine(pre, w, ctx);
  finish(pre, pr, ctx);
  return pr;
}

// Merges parts smaller than v_min into a neighbour (docs/algorithm.md §14.2), smallest first;
// parts without a neighbour they can join stay.
void merge_tiny_parts(const CellComplex& cx, std::vector<Work>& parts, double v_min) {
  for (int guard = 0; guard < 10000; ++guard) {
    std::unordered_map<uint32_t, uint32_t> owner;
    std::vector<double> vol(parts.size(), 0);
    for (uint32_t i = 0; i < parts.size(); ++i)
      for (uint32_t c : parts[i].cells) {
        owner[c] = i;
        vol[i] += cx.cell_volume(c);
      }
    int victim = -1;
    for (uint32_t i = 0; i < parts.size(); ++i)
      if (vol[i] < v_min && (victim < 0 || vol[i] < vol[victim])) victim = static_cast<int>(i);
    if (victim < 0) return;
    std::map<uint32_t, double> shared;
    for (uint32_t c : parts[victim].cells)
      for (uint32_t f : cx.cell(c).facets) {
        const uint32_t o = cx.other_side(f, c);
        auto it = o == CellComplex::kNone ? owner.end() : owner.find(o);
        if (it != owner.end() && it->second != static_cast<uint32_t>(victim)) shared[it->second] += cx.facet_area(f);
      }
    if (shared.empty()) {
      v_min = std::min(v_min, vol[victim]);  // isolated: keep it, look at larger ones only
      continue;
    }
    // Among the neighbours whose union with the victim stays 2-manifold, the one whose convex
    // hull grows least; then the largest shared area (the research code's rule). A sliver can be
    // long: merged into the neighbour it shares most area with, it can take a convex box's
    // convexity far down (docs/design.md, "Tiny parts merge where the hull grows least").
    auto hull_of = [&](const std::vector<uint32_t>& cells) {
      std::vector<uint32_t> ids;  // each vertex once (cells share them)
      for (uint32_t c : cells)
        for (uint32_t v : cx.cell_vertices(c)) ids.push_back(v);
      std::sort(ids.begin(), ids.end());
      ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
      std::vector<Vec3> pts;
      pts.reserve(ids.size());
      for (uint32_t v : ids) pts.push_back(cx.point(v));
      return convex_hull(pts).volume;
    };
    const double tol = 1e-9 * std::max(1.0, v_min);
    int target = -1;
    double best_growth = 0, best_area = 0;
    for (const auto& [p, area] : shared) {
      std::vector<uint32_t> merged = parts[p].cells;
      merged.insert(merged.end(), parts[victim].cells.begin(), parts[victim].cells.end());
      if (has_pinch_edge(cx, merged)) continue;
      const double growth = hull_of(merged) - hull_of(parts[p].cells) - vol[victim];
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
    parts.erase(parts.begin() + victim);
  }
}

// The cells of all parts of a level as one space (analysis of parts and of unions of parts).
struct LevelSpace {
  CellSpace space;
  std::unordered_map<uint32_t, uint32_t> local;  // global cell id -> index in `space`
  LevelSpace(const CellComplex& cx, const std::vector<Work>& work) {
    std::vector<uint32_t> all;
    for (const Work& w : work) all.insert(all.end(), w.cells.begin(), w.cells.end());
    std::sort(all.begin(), all.end());
    space = make_space(cx, all);
    for (uint32_t i = 0; i < all.size(); ++i) local[all[i]] = i;
  }
  Bits bits(const Work& w) const {
    Bits b(space.words(), 0);
    for (uint32_t c : w.cells) set_bit(b, local.at(c));
    return b;
  }
};

// Analysis only: generated candidate planes are not registered.
const PlaneResolver kNoNewPlanes = [](const Plane&, const std::vector<uint32_t>&) { return std::optional<uint32_t>{}; };

// Every part of a level analysed, in parallel (the analysis only reads the complex); in order.
std::vector<PartInfo> analyze_parts(const CellSpace& space, const LevelSpace& ls, const std::vector<Work>& work,
                                    const AnalysisContext& ctx) {
  std::vector<PartInfo> info(work.size());
  tbb::parallel_for(size_t(0), work.size(), [&](size_t i) { info[i] = analyze_part(space, ls.bits(work[i]), ctx, kNoNewPlanes); });
  return info;
}


// Merges neighbouring parts while that lowers the level's cost (docs/algorithm.md §14.3, with the
// whole-building normalisers of §11.3). The search is inflated (σ > 1), keeps only the best
// children and cuts whole parts by unbounded planes, so it often leaves two convex pieces whose
// union is still convex (a cut that also went through an unrelated wing), or nearly so. Merging
// such a pair removes a part at no loss of convexity; a merge is only taken if the union has no
// concave line significant at this level (the level would cut it again) and stays 2-manifold.
// Greedy, best decrease first; ties by part index (deterministic).
void merge_convex_neighbours(const Preprocessed& pre, const DecomposeParams& p, std::vector<Work>& work,
                             const AnalysisContext& ctx, const Objective& obj) {
  const CellComplex& cx = *pre.complex;
  if (work.size() < 2) return;
  const LevelSpace ls(cx, work);
  const CellSpace& space = ls.space;
  const auto& local = ls.local;
  // Cost change of replacing parts a and b by their union u (|P| drops by one).
  auto gain = [&](const PartInfo& a, const PartInfo& b, const PartInfo& u) {
    return obj.change(-1.0, u.delta - a.delta - b.delta, u.e_all - a.e_all - b.e_all);
  };
  std::vector<PartInfo> info = analyze_parts(space, ls, work, ctx);
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
  std::map<std::pair<uint32_t, uint32_t>, std::optional<std::pair<double, PartInfo>>> cache;
  auto evaluate = [&](uint32_t a, uint32_t b) -> const std::optional<std::pair<double, PartInfo>>& {
    auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    std::optional<std::pair<double, PartInfo>> r;
    Bits u = info[a].bits;
    for (size_t w = 0; w < u.size(); ++w) u[w] |= info[b].bits[w];
    PartInfo ui = analyze_part(space, std::move(u), ctx, kNoNewPlanes);
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
        if (b > a && alive[b] && work[a].component == work[b].component && !cache.count({a, b})) todo.emplace_back(a, b);
    }
    std::vector<PartInfo> unions(todo.size());
    tbb::parallel_for(size_t(0), todo.size(), [&](size_t i) {
      Bits u = info[todo[i].first].bits;
      for (size_t w = 0; w < u.size(); ++w) u[w] |= info[todo[i].second].bits[w];
      unions[i] = analyze_part(space, std::move(u), ctx, kNoNewPlanes);
    });
    for (size_t i = 0; i < todo.size(); ++i) {
      const auto [a, b] = todo[i];
      std::optional<std::pair<double, PartInfo>> r;
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
    PartInfo merged = cache[{a, b}]->second;
    work[a].cells.insert(work[a].cells.end(), work[b].cells.begin(), work[b].cells.end());
    std::sort(work[a].cells.begin(), work[a].cells.end());
    for (uint32_t c : work[b].cells) owner[local.at(c)] = a;
    work[b].cells.clear();
    alive[b] = false;
    info[a] = std::move(merged);
    for (auto it = cache.begin(); it != cache.end();)
      it = (it->first.first == a || it->first.second == a || it->first.first == b || it->first.second == b)
               ? cache.erase(it) : std::next(it);
  }
  std::vector<Work> kept;
  for (uint32_t i = 0; i < work.size(); ++i)
    if (alive[i]) kept.push_back(std::move(work[i]));
  work = std::move(kept);
}

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
void revisit_boundaries(Preprocessed& pre, const DecomposeParams& p, std::vector<Work> prev, std::vector<Work>& work,
                        const AnalysisContext& ctx, const Objective& obj, Clock::time_point deadline,
                        LevelResult& level) {
  CellComplex& cx = *pre.complex;
  if (prev.size() < 2 || work.size() < 3) return;
  DecomposeParams rp = p;
  rp.max_candidates = p.revisit_candidates;
  AnalysisContext rctx = ctx;
  rctx.dec = &rp;
  for (Work& w : prev) w.cells = current_leaves(cx, w.cells);
  for (Work& w : work) w.cells = current_leaves(cx, w.cells);
  std::unordered_map<uint32_t, uint32_t> prev_of, work_of;
  for (uint32_t i = 0; i < prev.size(); ++i)
    for (uint32_t c : prev[i].cells) prev_of[c] = i;
  for (uint32_t i = 0; i < work.size(); ++i)
    for (uint32_t c : work[i].cells) work_of[c] = i;
  // The previous part a piece lies in (-1: it straddles two, after a merge), and the pieces of each.
  std::vector<int64_t> home(work.size(), -1);
  std::vector<std::vector<uint32_t>> pieces(prev.size());
  for (uint32_t w = 0; w < work.size(); ++w) {
    auto it = prev_of.find(work[w].cells.front());
    if (it == prev_of.end()) continue;
    const uint32_t h = it->second;
    bool inside = true;
    for (uint32_t c : work[w].cells) {
      auto jt = prev_of.find(c);
      inside &= jt != prev_of.end() && jt->second == h;
    }
    if (inside) {
      home[w] = h;
      pieces[h].push_back(w);
    }
  }
  struct Candidate {
    int component = 0;
    std::vector<uint32_t> old_pieces;
    double old_delta = 0, old_e = 0;
    int old_sig = 0;
    Prepared pr;
    SearchResult sr;
  };
  std::vector<Candidate> cands;
  // A previous part whose cells are not all in clean pieces (a merge crossed it) is left alone.
  std::vector<bool> clean(prev.size());
  for (uint32_t i = 0; i < prev.size(); ++i) {
    size_t covered = 0;
    for (uint32_t w : pieces[i]) covered += work[w].cells.size();
    clean[i] = covered == prev[i].cells.size();
  }
  // Pieces sharing a facet, and the pieces' share of the level's cost (analysed once each, when
  // a union first needs it).
  std::vector<std::vector<uint32_t>> touches(work.size());
  for (uint32_t w = 0; w < work.size(); ++w) touches[w] = neighbour_owners(cx, work[w].cells, w, lookup_in(work_of));
  std::vector<std::optional<PartInfo>> piece_info(work.size());
  auto info_of = [&](uint32_t w) -> const PartInfo& {
    if (!piece_info[w]) {
      const CellSpace space = make_space(cx, current_leaves(cx, work[w].cells));
      piece_info[w] = analyze_part(space, space.all(), ctx, kNoNewPlanes);
    }
    return *piece_info[w];
  };
  // Only the pieces along the boundary of a and b are searched again: that boundary is what a
  // joint search can move, and the union stays small. Empty unless three or more, connected.
  auto border_of = [&](uint32_t a, uint32_t b) {
    std::vector<uint32_t> border;
    for (const auto& side : {std::make_pair(a, b), std::make_pair(b, a)}) {
      const int64_t other = side.second;  // (clang cannot capture a structured binding)
      for (uint32_t w : pieces[side.first])
        if (std::any_of(touches[w].begin(), touches[w].end(), [&](uint32_t t) { return home[t] == other; }))
          border.push_back(w);
    }
    if (border.size() < 3) return std::vector<uint32_t>{};
    std::set<uint32_t> seen{border.front()};
    std::vector<uint32_t> stack{border.front()};
    while (!stack.empty()) {
      const uint32_t w = stack.back();
      stack.pop_back();
      for (uint32_t t : touches[w])
        if (std::find(border.begin(), border.end(), t) != border.end() && seen.insert(t).second) stack.push_back(t);
    }
    return seen.size() == border.size() ? border : std::vector<uint32_t>{};
  };
  for (uint32_t a = 0; a < prev.size() && Clock::now() <= deadline; ++a)
    for (uint32_t b : neighbour_owners(cx, prev[a].cells, a, lookup_in(prev_of))) {
      if (b < a || prev[b].component != prev[a].component || !clean[a] || !clean[b]) continue;
      const std::vector<uint32_t> border = border_of(a, b);
      if (border.empty()) continue;
      Candidate cd;
      cd.component = prev[a].component;
      cd.old_pieces = border;
      Work u{{}, cd.component};
      for (uint32_t w : border) {
        const PartInfo& info = info_of(w);
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
      // Searched at once: a later union's refinement may split these cells, and their facets then
      // face the children (a search on them would see wrong orientations). Its parts stay valid as
      // regions (read back through the current leaves).
      cd.sr = search(cd.pr.input, cd.pr.root);
      cd.pr.input.positive.clear();
      cands.push_back(std::move(cd));
    }
  std::vector<std::pair<double, size_t>> gains;
  for (size_t i = 0; i < cands.size(); ++i) {
    const Candidate& cd = cands[i];
    level.nodes_expanded += cd.sr.expanded;
    if (cd.sr.deadline_hit || cd.sr.parts.empty() || cd.sr.parts.size() > cd.old_pieces.size()) continue;
    double sum_delta = 0, sum_e = 0;
    int sum_sig = 0;
    for (const PartInfo& part : cd.sr.parts) {
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
  std::vector<bool> removed(work.size(), false);
  std::vector<Work> added;
  for (const auto& [gain, i] : gains) {
    const Candidate& cd = cands[i];
    if (std::any_of(cd.old_pieces.begin(), cd.old_pieces.end(), [&](uint32_t w) { return removed[w]; })) continue;
    for (uint32_t w : cd.old_pieces) removed[w] = true;
    for (const PartInfo& part : cd.sr.parts) {
      Work nw{{}, cd.component};
      for (uint32_t k = 0; k < cd.pr.space.cells.size(); ++k)
        if (test_bit(part.bits, k)) nw.cells.push_back(cd.pr.space.cells[k]);
      added.push_back(std::move(nw));
    }
  }
  for (Work& w : work) w.cells = current_leaves(cx, w.cells);
  for (Work& w : added) w.cells = current_leaves(cx, w.cells);
  if (added.empty()) return;
  std::vector<Work> next;
  for (uint32_t w = 0; w < work.size(); ++w)
    if (!removed[w]) next.push_back(std::move(work[w]));
  for (Work& w : added) next.push_back(std::move(w));
  work = std::move(next);
}

// A part's convexity V/V_CH as reported (1 for an exactly convex part).
double reported_convexity(const PartInfo& info) {
  return info.delta == 0 && !info.nearly_convex ? 1.0 : info.convexity();
}

// A part's term V·(V/V_CH) of the level's volume-weighted convexity.
double weighted_convexity(const PartInfo& info) { return info.volume * reported_convexity(info); }

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
void refuse_costly_cuts(const Preprocessed& pre, const DecomposeParams& p, const std::vector<Work>& prev,
                        std::vector<Work>& work, const AnalysisContext& ctx, const Objective& obj) {
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
  if (std::none_of(parts_of.begin(), parts_of.end(), [](const auto& e) { return e.second.size() > 1; })) return;
  const LevelSpace ls(cx, work);
  std::vector<PartInfo> info;
  double weighted = 0, volume = 0;
  info = analyze_parts(ls.space, ls, work, ctx);
  for (const PartInfo& pi : info) {
    weighted += weighted_convexity(pi);
    volume += pi.volume;
  }
  std::vector<std::tuple<double, uint32_t, double>> costly;  // (cost change, group, Σ V·convexity lost)
  for (const auto& [g, js] : parts_of) {
    const std::vector<uint32_t>& qs = prevs_of[g];
    if (js.size() <= 1) continue;  // a group that is one part is its one previous part
    double d_delta = 0, d_weighted = 0;
    int d_e = 0;
    bool stays_cut = false;  // a previous part would be pinched, or less convex than uncut_convexity
    for (uint32_t q : qs) {
      Bits whole(ls.space.words(), 0);
      for (uint32_t c : prev_cells[q]) set_bit(whole, ls.local.at(c));
      const PartInfo qi = analyze_part(ls.space, std::move(whole), ctx, kNoNewPlanes);
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
    return std::get<0>(a) != std::get<0>(b) ? std::get<0>(a) > std::get<0>(b) : std::get<1>(a) < std::get<1>(b);
  });
  std::vector<bool> restore(prev.size(), false);
  for (const auto& [change, g, lost] : costly) {
    if (volume <= 0 || (weighted - lost) / volume < p.cvx_thresh) continue;
    weighted -= lost;
    restore[g] = true;
  }
  // The level's parts in order; a restored group's previous parts take its first part's place.
  std::vector<Work> next;
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

// Whole-building statistics of a level (normalised by the singleton cell R, docs/algorithm.md §11.3).
void level_statistics(const Preprocessed& pre, const DecomposeParams& p, const std::vector<Work>& work,
                      const AnalysisContext& ctx, const Objective& obj, LevelResult& out) {
  const CellComplex& cx = *pre.complex;
  const LevelSpace ls(cx, work);
  const CellSpace& space = ls.space;
  std::unordered_map<uint32_t, uint32_t> owner;
  for (uint32_t i = 0; i < work.size(); ++i)
    for (uint32_t c : work[i].cells) owner[c] = i;
  double sum_delta = 0, sum_v = 0, wsum = 0;
  int sum_e = 0;
  out.parts.clear();
  out.min_convexity = 1;
  out.mean_convexity = 0;
  const std::vector<PartInfo> infos = analyze_parts(space, ls, work, ctx);
  for (uint32_t i = 0; i < work.size(); ++i) {
    const PartInfo& info = infos[i];
    PartResult r;
    r.cells = work[i].cells;
    r.component = work[i].component;
    r.volume = info.volume;
    r.hull_volume = info.hull_volume;
    r.convexity = reported_convexity(info);
    r.neighbours = neighbour_owners(cx, work[i].cells, i, lookup_in(owner));
    sum_delta += info.delta;
    sum_e += info.e_all;
    sum_v += info.volume;
    wsum += info.volume * r.convexity;
    out.min_convexity = std::min(out.min_convexity, r.convexity);
    out.mean_convexity += r.convexity;
    out.parts.push_back(std::move(r));
  }
  out.mean_convexity /= std::max<size_t>(1, work.size());
  out.convexity = sum_v > 0 ? wsum / sum_v : 0;
  out.remaining_concave = sum_e;
  out.g = obj.g(work.size(), sum_delta);
  out.h = obj.h(sum_e, sum_delta);
  out.cost = out.g + p.sigma * out.h;
}

}  // namespace

Decomposition decompose(Preprocessed& pre, const DecomposeParams& p, Clock::time_point deadline) {
  const auto t0 = Clock::now();
  Decomposition out;
  CellComplex& cx = *pre.complex;
  std::vector<Work> work;
  for (size_t i = 0; i < pre.components.size(); ++i) work.push_back({pre.components[i].cells, static_cast<int>(i)});
  double total_volume = 0;
  for (const auto& c : pre.components) total_volume += c.volume;

  // Whole-building normalisers from the singleton cell R (all components together).
  Objective obj = Objective::of_root(0, 0, p);
  {
    std::vector<uint32_t> all;
    for (const Work& w : work) all.insert(all.end(), w.cells.begin(), w.cells.end());
    std::sort(all.begin(), all.end());
    const CellSpace space = make_space(cx, all);
    const PartInfo r = analyze_part(space, space.all(), make_context(pre, p, p.levels.empty() ? 0 : p.levels.front()), kNoNewPlanes);
    out.concave_edges = r.e_all;
    obj = Objective::of_root(r.e_all, r.delta, p);
  }

  for (size_t li = 0; li < p.levels.size(); ++li) {
    const auto tl = Clock::now();
    LevelResult level;
    level.lod = p.levels[li];
    // The first level searches whole components: one search each, whose boundaries every later
    // level keeps, so it may choose among more candidate planes (first_level_candidates, opt-in).
    // Not the default: the inflated search (sigma = 2, child cap) is not monotone in its
    // candidates, and a cheaper first level can bind the finer levels badly (docs/algorithm.md
    // §13, docs/design.md "A wider first level").
    DecomposeParams level_params = p;
    if (li == 0 && p.first_level_candidates >= 0) level_params.max_candidates = p.first_level_candidates;
    const AnalysisContext ctx = make_context(pre, level_params, level.lod);
    for (Work& w : work) w.cells = current_leaves(cx, w.cells);
    if (Clock::now() <= deadline) {
      std::vector<Prepared> prepared;
      prepared.reserve(work.size());
      for (const Work& w : work) {
        prepared.push_back(refine(pre, w, ctx));
        prepared.back().input.deadline = deadline;
      }
      for (Prepared& pr : prepared) finish_space(pre, pr, ctx);
      tbb::parallel_for(size_t(0), prepared.size(), [&](size_t i) { finish_root(pre, prepared[i], ctx); });
      for (Prepared& pr : prepared) pr.input.space = &pr.space;
      std::vector<SearchResult> results(work.size());
      auto run_one = [&](size_t i) {
        if (prepared[i].search) results[i] = search(prepared[i].input, prepared[i].root);
      };
      tbb::parallel_for(size_t(0), work.size(), run_one);
      std::vector<Work> next;
      for (size_t i = 0; i < work.size(); ++i) {
        if (!prepared[i].search) {
          next.push_back({current_leaves(cx, work[i].cells), work[i].component});
          continue;
        }
        const SearchResult& sr = results[i];
        level.nodes_expanded += sr.expanded;
        level.truncated |= sr.deadline_hit || sr.budget_hit;
        if (sr.deadline_hit) {
          out.partial = true;
          out.reason = "deadline reached during the search at LoD " + std::to_string(level.lod);
        }
        for (const PartInfo& part : sr.parts) {
          Work nw{{}, work[i].component};
          for (uint32_t k = 0; k < prepared[i].space.cells.size(); ++k)
            if (test_bit(part.bits, k)) nw.cells.push_back(prepared[i].space.cells[k]);
          next.push_back(std::move(nw));
        }
      }
      std::vector<Work> prev = std::move(work);
      work = std::move(next);
      if (p.revisit_boundaries && li > 0)  // (takes its own copy of prev: the undo below needs it)
        revisit_boundaries(pre, p, prev, work, ctx, obj, deadline, level);
      if (p.merge_tiny_parts) merge_tiny_parts(cx, work, 0.1 * level.lod * total_volume);
      if (p.merge_convex_parts) merge_convex_neighbours(pre, p, work, ctx, obj);
      if (p.uncut_convexity < 1) refuse_costly_cuts(pre, p, prev, work, ctx, obj);
    } else {
      out.partial = true;
      if (out.reason.empty()) out.reason = "deadline reached before LoD " + std::to_string(level.lod);
      level.truncated = true;
    }
    level_statistics(pre, p, work, ctx, obj, level);
    level.seconds = seconds_since(tl);
    out.levels.push_back(std::move(level));
  }
  out.seconds = seconds_since(t0);
  return out;
}

namespace {
PolygonMesh surface_to_mesh(const Preprocessed& pre, const Surface& s) {
  const CellComplex& cx = *pre.complex;
  PolygonMesh labels;  // the input's labels plus ClosureSurface for cut faces
  labels.semantic_labels = pre.labels;
  const int32_t closure = labels.label_index("ClosureSurface");
  PolygonMesh m = to_polygon_mesh(cx, s, Vec3{}, [&](const SurfaceFace& f) {
    if (f.cut || pre.planes->origin(f.plane) != PlaneOrigin::Region) return closure;
    return pre.label_of_plane(f.plane);
  });
  m.semantic_labels = std::move(labels.semantic_labels);
  for (Vec3& v : m.vertices) v = pre.to_input(v);
  for (size_t i = 0; i < s.faces.size(); ++i)
    if (s.faces[i].neighbour != CellComplex::kNone) m.faces[i].neighbour = static_cast<int32_t>(s.faces[i].neighbour);
  return m;
}

PolygonMesh surface_mesh(const Preprocessed& pre, const std::vector<uint32_t>& cells, const std::vector<uint32_t>* solid) {
  return surface_to_mesh(pre, extract_surface(*pre.complex, cells, solid));
}

std::vector<uint32_t> all_singleton_cells(const Preprocessed& pre) {
  std::vector<uint32_t> all;
  for (const auto& c : pre.components)
    for (uint32_t x : c.cells) pre.complex->leaves(x, all);
  std::sort(all.begin(), all.end());
  return all;
}
}  // namespace

PolygonMesh part_mesh(const Preprocessed& pre, const PartResult& part) {
  const std::vector<uint32_t> solid = all_singleton_cells(pre);
  return surface_mesh(pre, current_leaves(*pre.complex, part.cells), &solid);
}

std::vector<PolygonMesh> level_part_meshes(const Preprocessed& pre, const std::vector<PartResult>& parts) {
  const CellComplex& cx = *pre.complex;
  const std::vector<uint32_t> solid = all_singleton_cells(pre);
  std::vector<std::vector<uint32_t>> leaves;
  std::unordered_map<uint32_t, uint32_t> part_of;
  for (size_t p = 0; p < parts.size(); ++p) {
    leaves.push_back(current_leaves(cx, parts[p].cells));
    for (uint32_t c : leaves.back()) part_of[c] = static_cast<uint32_t>(p);
  }
  // The corners of every part's faces; a part that dropped one of them is extracted again keeping
  // them (the drop rule depends on the part alone, so the others are already right).
  // Each part's surface only reads the complex: extracted in parallel, in part order.
  std::vector<Surface> surfaces(leaves.size());
  tbb::parallel_for(size_t(0), leaves.size(),
                    [&](size_t p) { surfaces[p] = extract_surface(cx, leaves[p], &solid, {&part_of, nullptr}); });
  std::unordered_set<uint32_t> corners;
  for (const Surface& s : surfaces)
    for (const auto& f : s.faces)
      for (const auto& r : f.rings) corners.insert(r.begin(), r.end());
  std::vector<PolygonMesh> out(leaves.size());
  tbb::parallel_for(size_t(0), leaves.size(), [&](size_t p) {
    const auto& dropped = surfaces[p].dropped;
    if (std::any_of(dropped.begin(), dropped.end(), [&](uint32_t v) { return corners.count(v) > 0; }))
      surfaces[p] = extract_surface(cx, leaves[p], &solid, {&part_of, &corners});
    out[p] = surface_to_mesh(pre, surfaces[p]);
  });
  return out;
}

PolygonMesh singleton_mesh(const Preprocessed& pre) {
  const std::vector<uint32_t> solid = all_singleton_cells(pre);
  return surface_mesh(pre, solid, nullptr);
}

}  // namespace mc
