#include "core/decompose.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "core/level_passes.hpp"
#include "core/level_work.hpp"
#include "core/search.hpp"
#include "core/surface.hpp"
#include "core/union_find.hpp"
#include "core/thread_tag.hpp"

namespace mc {

namespace {

using namespace level;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Whole-building statistics of a level (normalised by the singleton cell R, docs/algorithm.md §11.3).
void level_statistics(const Preprocessed& pre, const std::vector<LevelPart>& work, const AnalysisContext& ctx,
                      const Objective& obj, LevelResult& out) {
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
  const std::vector<PartAnalysis> infos = analyze_parts(space, ls, work, ctx);
  for (uint32_t i = 0; i < work.size(); ++i) {
    const PartAnalysis& info = infos[i];
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
  out.cost = obj.cost(out.g, out.h);
}

}  // namespace

Decomposition decompose(Preprocessed& pre, const DecomposeParams& p, Clock::time_point deadline) {
  const auto t0 = Clock::now();
  Decomposition out;
  CellComplex& cx = *pre.complex;
  std::vector<LevelPart> work;
  for (size_t i = 0; i < pre.components.size(); ++i)
    work.push_back({pre.components[i].cells, static_cast<int>(i)});
  double total_volume = 0;
  for (const auto& c : pre.components) total_volume += c.volume;

  HullCache hulls;  // every analysis of this building's parts (core/hull_cache.hpp)
  // Whole-building normalisers from the singleton cell R (all components together).
  Objective obj = Objective::of_root(0, 0, p);
  {
    std::vector<uint32_t> all;
    for (const LevelPart& w : work) all.insert(all.end(), w.cells.begin(), w.cells.end());
    std::sort(all.begin(), all.end());
    const CellSpace space = make_space(cx, all);
    AnalysisContext root_ctx = make_context(pre, p, p.levels.empty() ? 0 : p.levels.front());
    root_ctx.hulls = &hulls;
    const PartAnalysis r = analyze_part(space, space.all(), root_ctx, kNoNewPlanes);
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
    AnalysisContext ctx = make_context(pre, level_params, level.lod);
    ctx.hulls = &hulls;
    LevelAnalyses analyses;
    for (LevelPart& w : work) w.cells = current_leaves(cx, w.cells);
    if (Clock::now() <= deadline) {
      std::vector<PreparedPart> prepared;
      prepared.reserve(work.size());
      for (const LevelPart& w : work) {
        prepared.push_back(refine(pre, w, ctx));
        prepared.back().input.deadline = deadline;
      }
      for (PreparedPart& pr : prepared) finish_space(pre, pr, ctx);
      tbb::parallel_for(size_t(0), prepared.size(),
                        with_thread_tag([&](size_t i) { finish_root(pre, prepared[i], ctx); }));
      for (PreparedPart& pr : prepared) pr.input.space = &pr.space;
      std::vector<SearchResult> results(work.size());
      auto run_one = [&](size_t i) {
        if (prepared[i].search) results[i] = search(prepared[i].input, prepared[i].root);
      };
      tbb::parallel_for(size_t(0), work.size(), with_thread_tag(run_one));
      std::vector<LevelPart> next;
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
        for (const PartAnalysis& part : sr.parts) {
          LevelPart nw{{}, work[i].component};
          for (uint32_t k = 0; k < prepared[i].space.cells.size(); ++k)
            if (test_bit(part.bits, k)) nw.cells.push_back(prepared[i].space.cells[k]);
          next.push_back(std::move(nw));
        }
      }
      std::vector<LevelPart> prev = std::move(work);
      work = std::move(next);
      if (p.revisit_boundaries && li > 0)  // (takes its own copy of prev: the undo below needs it)
        revisit_boundaries(pre, p, prev, work, ctx, obj, deadline, level);
      ctx.parts = &analyses;  // from here on the complex does not change within the level
      if (p.merge_tiny_parts) merge_tiny_parts(cx, work, 0.1 * level.lod * total_volume, &hulls);
      if (p.merge_convex_parts) merge_convex_neighbours(pre, work, ctx, obj);
      if (p.uncut_convexity < 1) refuse_costly_cuts(pre, p, prev, work, ctx, obj);
    } else {
      out.partial = true;
      if (out.reason.empty()) out.reason = "deadline reached before LoD " + std::to_string(level.lod);
      level.truncated = true;
    }
    level_statistics(pre, work, ctx, obj, level);
    level.seconds = seconds_since(tl);
    out.levels.push_back(std::move(level));
  }
  out.seconds = seconds_since(t0);
  return out;
}

Decomposition decompose_measuring_fidelity(Preprocessed& pre, const DecomposeParams& p,
                                           Clock::time_point deadline) {
  Decomposition out;
  // measure_fidelity() touches only pre.pending_fidelity and the Hausdorff fields, which
  // decompose() never reads. Each side catches its own error: an exception escaping one would
  // cancel the other's parallel loops halfway. The measure is taken whether or not the levels
  // fail (a failed building still reports its cell's fidelity); the levels' error comes first.
  std::exception_ptr measure_error, levels_error;
  tbb::parallel_invoke(with_thread_tag([&] {
                         try {
                           measure_fidelity(pre);
                         } catch (...) { measure_error = std::current_exception(); }
                       }),
                       with_thread_tag([&] {
                         try {
                           out = decompose(pre, p, deadline);
                         } catch (...) { levels_error = std::current_exception(); }
                       }));
  if (levels_error) std::rethrow_exception(levels_error);
  if (measure_error) std::rethrow_exception(measure_error);
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
    if (s.faces[i].neighbour != CellComplex::kNone)
      m.faces[i].neighbour = static_cast<int32_t>(s.faces[i].neighbour);
  return m;
}

PolygonMesh surface_mesh(const Preprocessed& pre, const std::vector<uint32_t>& cells,
                         const std::vector<uint32_t>* solid) {
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
  tbb::parallel_for(size_t(0), leaves.size(), with_thread_tag([&](size_t p) {
                      surfaces[p] = extract_surface(cx, leaves[p], &solid, {&part_of, nullptr});
                    }));
  std::unordered_set<uint32_t> corners;
  for (const Surface& s : surfaces)
    for (const auto& f : s.faces)
      for (const auto& r : f.rings) corners.insert(r.begin(), r.end());
  std::vector<PolygonMesh> out(leaves.size());
  tbb::parallel_for(
      size_t(0), leaves.size(), with_thread_tag([&](size_t p) {
        const auto& dropped = surfaces[p].dropped;
        if (std::any_of(dropped.begin(), dropped.end(), [&](uint32_t v) { return corners.count(v) > 0; }))
          surfaces[p] = extract_surface(cx, leaves[p], &solid, {&part_of, &corners});
        out[p] = surface_to_mesh(pre, surfaces[p]);
      }));
  return out;
}

PolygonMesh singleton_mesh(const Preprocessed& pre) {
  const std::vector<uint32_t> solid = all_singleton_cells(pre);
  return surface_mesh(pre, solid, nullptr);
}

}  // namespace mc