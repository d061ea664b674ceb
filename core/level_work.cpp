#include "core/level_work.hpp"
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

std::vector<uint32_t> current_leaves(const CellComplex& cx, const std::vector<uint32_t>& cells) {
  std::vector<uint32_t> out;
  for (uint32_t c : cells) cx.leaves(c, out);
  std::sort(out.begin(), out.end());
  return out;
}

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

PreparedPart refine(Preprocessed& pre, const LevelPart& w, const AnalysisContext& ctx) {
  CellComplex& cx = *pre.complex;
  PlaneRegistry& reg = *pre.planes;
  PreparedPart pr;
  CellSpace coarse = make_space(cx, w.cells);
  const PlaneResolver add = [&](const Plane& g,
                                const std::vector<uint32_t>& pool) -> std::optional<uint32_t> {
    return reg.add_snapped(g, pool, ctx.angle_rad, ctx.dist, ctx.box, PlaneOrigin::Candidate);
  };
  PartAnalysis info = analyze_part(coarse, coarse.all(), ctx, add);
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
  const double hair = pre.hair;
  auto hair_close = [&](uint32_t c, uint32_t plane) {
    const Plane& pl = reg[plane];
    for (uint32_t v : cx.cell_vertices(c)) {
      const double s = std::abs(pl.signed_distance(cx.point(v)));
      if (s < hair && cx.vertex_side(v, plane) != 0) return true;
    }
    return false;
  };
  for (uint32_t plane : info.candidates) {
    // The hair tests first, in parallel for many cells: a split along `plane` adds vertices only
    // on it, which the test ignores, so testing before the splits is testing between them.
    cx.prepare_side_predicates();
    std::vector<uint8_t> close(cells.size());
    auto test = [&](size_t i) { close[i] = hair_close(cells[i], plane); };
    if (cells.size() >= 32) {
      tbb::parallel_for(size_t(0), cells.size(), with_thread_tag(test));
    } else {
      for (size_t i = 0; i < cells.size(); ++i) test(i);
    }
    std::vector<uint32_t> next;
    for (size_t i = 0; i < cells.size(); ++i) {
      const uint32_t c = cells[i];
      if (close[i]) {
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

// The refined space (serial: the complex measures cells lazily) and the cells on each candidate's
// positive side (exact predicates, one candidate per task once the exact planes are built).
void finish_space(const Preprocessed& pre, PreparedPart& pr, const AnalysisContext& ctx) {
  if (!pr.search) return;
  pre.complex->prepare_side_predicates();
  const CellComplex& cx = *pre.complex;
  pr.space = make_space(cx, std::vector<uint32_t>(pr.space.cells));
  const std::vector<uint32_t>& cells = pr.space.cells;
  const std::vector<uint32_t>& pool = pr.input.pool;
  pr.input.positive.assign(pool.size(), Bits(pr.space.words(), 0));
  std::vector<std::vector<uint32_t>> vertices(cells.size());  // each cell's, once for every candidate
  tbb::parallel_for(size_t(0), cells.size(),
                    with_thread_tag([&](size_t i) { vertices[i] = cx.cell_vertices(cells[i]); }));
  tbb::parallel_for(size_t(0), pool.size(), with_thread_tag([&](size_t k) {
                      for (uint32_t i = 0; i < cells.size(); ++i)
                        if (cx.vertices_side(vertices[i], pool[k]) > 0) set_bit(pr.input.positive[k], i);
                    }));
  pr.input.ctx = ctx;
}

// The search's root: the refined space analysed (reads only; several at once are fine).
void finish_root(const Preprocessed& pre, PreparedPart& pr, const AnalysisContext& ctx) {
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

void finish(const Preprocessed& pre, PreparedPart& pr, const AnalysisContext& ctx) {
  finish_space(pre, pr, ctx);
  finish_root(pre, pr, ctx);
}

PreparedPart prepare(Preprocessed& pre, const LevelPart& w, const AnalysisContext& ctx) {
  PreparedPart pr = refine(pre, w, ctx);
  finish(pre, pr, ctx);
  return pr;
}

LevelSpace::LevelSpace(const CellComplex& cx, const std::vector<LevelPart>& work) {
  std::vector<uint32_t> all;
  for (const LevelPart& w : work) all.insert(all.end(), w.cells.begin(), w.cells.end());
  std::sort(all.begin(), all.end());
  space = make_space(cx, all);
  for (uint32_t i = 0; i < all.size(); ++i) local[all[i]] = i;
}

Bits LevelSpace::bits(const LevelPart& w) const {
  Bits b(space.words(), 0);
  for (uint32_t c : w.cells) set_bit(b, local.at(c));
  return b;
}

const PlaneResolver kNoNewPlanes = [](const Plane&, const std::vector<uint32_t>&) {
  return std::optional<uint32_t>{};
};

std::vector<PartAnalysis> analyze_parts(const CellSpace& space, const LevelSpace& ls,
                                        const std::vector<LevelPart>& work, const AnalysisContext& ctx) {
  std::vector<PartAnalysis> info(work.size());
  LevelAnalyses* memo = ctx.parts;
  if (memo && memo->cells != space.cells) {  // another space: other bits
    memo->by_part_cells.clear();
    memo->cells = space.cells;
  }
  std::vector<std::vector<uint32_t>> keys(work.size());
  std::vector<size_t> todo;
  for (size_t i = 0; i < work.size(); ++i) {
    if (memo) {
      keys[i] = work[i].cells;
      std::sort(keys[i].begin(), keys[i].end());
      if (auto it = memo->by_part_cells.find(keys[i]); it != memo->by_part_cells.end()) {
        info[i] = it->second;
        continue;
      }
    }
    todo.push_back(i);
  }
  tbb::parallel_for(size_t(0), todo.size(), with_thread_tag([&](size_t k) {
                      const size_t i = todo[k];
                      info[i] = analyze_part(space, ls.bits(work[i]), ctx, kNoNewPlanes);
                    }));
  if (memo)
    for (size_t i : todo) memo->by_part_cells.emplace(std::move(keys[i]), info[i]);
  return info;
}

}  // namespace mc::level
