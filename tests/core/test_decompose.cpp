#include "core/decompose.hpp"
#include "core/level_work.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <optional>
#include <tuple>

#include <tbb/global_control.h>

#include "buildings.hpp"
#include "off_fixture.hpp"

namespace mc {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  Preprocessed pre;
  Decomposition dec;
};

Outcome run(const PolygonMesh& m, double cell = 0.5, DecomposeParams dp = {}) {
  PreprocessParams pp;
  pp.cell_size = cell;
  pp.dist_thresh = cell / 4;
  pp.compute_hausdorff = false;
  const auto deadline = Clock::now() + std::chrono::seconds(120);
  Outcome r{preprocess(m, pp, deadline), {}};
  r.dec = decompose(r.pre, dp, deadline);
  return r;
}

using Key = std::tuple<double, double, double>;
Key key(const Vec3& v) { return {std::round(v.x * 1e6), std::round(v.y * 1e6), std::round(v.z * 1e6)}; }

// Every edge of a closed, oriented polygon surface is used once in each direction.
void expect_closed(const PolygonMesh& m) {
  std::map<std::pair<Key, Key>, int> edges;
  for (const auto& f : m.faces)
    for (const auto& r : f.rings)
      for (size_t i = 0; i < r.size(); ++i)
        edges[{key(m.vertices[r[i]]), key(m.vertices[r[(i + 1) % r.size()]])}]++;
  for (const auto& [e, n] : edges) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(edges.count({e.second, e.first}), 1u);
  }
}

double mesh_volume(const PolygonMesh& m) {
  double v = 0;
  for (const auto& f : m.faces)
    for (const auto& r : f.rings)
      for (size_t i = 1; i + 1 < r.size(); ++i)
        v += dot(m.vertices[r[0]], cross(m.vertices[r[i]], m.vertices[r[i + 1]])) / 6.0;
  return v;
}

// The singleton cell's volume (all components): every level's parts must add up to it.
double cell_volume(const Outcome& r) {
  double v = 0;
  for (const auto& c : r.pre.components) v += c.volume;
  return v;
}

void expect_valid_levels(const Outcome& r, double volume) {
  ASSERT_FALSE(r.dec.levels.empty());
  for (const auto& level : r.dec.levels) {
    double sum = 0;
    for (const auto& part : level.parts) {
      sum += part.volume;
      const PolygonMesh m = part_mesh(r.pre, part);
      expect_closed(m);
      EXPECT_NEAR(mesh_volume(m), part.volume, 1e-6 * volume);
    }
    EXPECT_NEAR(sum, volume, 1e-9 * volume);  // parts tile the singleton cell
  }
}

// Preprocesses paper sample `name` with its published parameters and decomposes it with `dp`
// (nullopt when the shared samples are not there).
std::optional<Outcome> run_sample(const std::string& name, const DecomposeParams& dp) {
  for (const auto& s : test::samples()) {
    if (s.name != name) continue;
    const auto deadline = Clock::now() + std::chrono::seconds(120);
    Outcome r{preprocess(test::load_off(s.off.string()), test::paper_params(s), deadline), {}};
    r.dec = decompose(r.pre, dp, deadline);
    return r;
  }
  return std::nullopt;
}

TEST(Decompose, BoxGivesOnePart) {
  const Outcome r = run(test::box_building());
  ASSERT_EQ(r.pre.components.size(), 1u);
  EXPECT_NEAR(r.pre.components[0].volume, 300.0, 1e-6);
  EXPECT_EQ(r.dec.concave_edges, 0);
  EXPECT_EQ(r.dec.levels.back().parts.size(), 1u);
  EXPECT_NEAR(r.dec.levels.back().convexity, 1.0, 1e-9);
  expect_valid_levels(r, 300.0);
}

// A 20 x 10 x 10 block with a 0.5 x 1 notch at one corner: 99.87% convex. With the default
// cvx_thresh (0.995) it stays one part; requiring exact convexity cuts it into two.
TEST(Decompose, NearlyConvexPartIsNotCut) {
  PolygonMesh m;
  test::add_prism(m, {{0, 0}, {20, 0}, {20, 9}, {19.5, 9}, {19.5, 10}, {0, 10}}, 0, 10);
  const double vol = 2000.0 - 0.5 * 1 * 10;
  const Outcome loose = run(m);
  EXPECT_NEAR(loose.pre.components[0].volume, vol, 1e-6);
  EXPECT_EQ(loose.dec.levels.back().parts.size(), 1u);
  // Reported as it is: the hull cuts the notch's corner diagonally (0.5 x 1 / 2 x 10 less).
  EXPECT_NEAR(loose.dec.levels.back().convexity, vol / (2000.0 - 2.5), 1e-9);
  expect_valid_levels(loose, vol);
  DecomposeParams exact;
  exact.cvx_thresh = 1.0;
  const Outcome strict = run(m, 0.5, exact);
  EXPECT_EQ(strict.dec.levels.back().parts.size(), 2u);
  EXPECT_NEAR(strict.dec.levels.back().min_convexity, 1.0, 1e-9);
  expect_valid_levels(strict, vol);
}

TEST(Decompose, LShapeGivesTwoConvexParts) {
  const Outcome r = run(test::l_building());
  const double vol = (12 * 5 + 5 * 7) * 6.0;
  EXPECT_NEAR(r.pre.components[0].volume, vol, 1e-6);
  EXPECT_EQ(r.dec.concave_edges, 1);
  EXPECT_EQ(r.dec.levels.back().parts.size(), 2u);
  EXPECT_NEAR(r.dec.levels.back().min_convexity, 1.0, 1e-9);
  expect_valid_levels(r, vol);
}

TEST(Decompose, UShapeGivesThreeConvexParts) {
  const Outcome r = run(test::u_building());
  const double vol = (15 * 5 + 2 * 5 * 7) * 6.0;
  EXPECT_EQ(r.dec.concave_edges, 2);
  EXPECT_EQ(r.dec.levels.back().parts.size(), 3u);
  EXPECT_NEAR(r.dec.levels.back().min_convexity, 1.0, 1e-9);
  expect_valid_levels(r, vol);
}

TEST(Decompose, CourtyardRingDecomposesIntoConvexParts) {
  const Outcome r = run(test::courtyard_building());
  const double vol = (16 * 16 - 6 * 6) * 6.0;
  EXPECT_NEAR(r.pre.components[0].volume, vol, 1e-6);
  EXPECT_EQ(r.dec.concave_edges, 4);
  const auto& last = r.dec.levels.back();
  EXPECT_GE(last.parts.size(), 4u);
  EXPECT_LE(last.parts.size(), 8u);
  EXPECT_NEAR(last.min_convexity, 1.0, 1e-9);
  expect_valid_levels(r, vol);
}

TEST(Decompose, SteppedTowerSplitsAtTheSetback) {
  const Outcome r = run(test::stepped_tower());
  const double vol = 10 * 10 * 4 + 4 * 4 * 8;
  EXPECT_NEAR(r.pre.components[0].volume, vol, 1e-6);
  const auto& last = r.dec.levels.back();
  EXPECT_EQ(last.parts.size(), 2u);
  EXPECT_NEAR(last.min_convexity, 1.0, 1e-9);
  expect_valid_levels(r, vol);
}

TEST(Decompose, CutFacesAreClosureSurfaces) {
  const Outcome r = run(test::l_building());
  const PolygonMesh m = part_mesh(r.pre, r.dec.levels.back().parts[0]);
  int closure = 0;
  for (const auto& f : m.faces)
    if (f.semantic >= 0 && m.semantic_labels[f.semantic] == "ClosureSurface") ++closure;
  EXPECT_EQ(closure, 1);
}

// Revisiting previous-level boundaries (decompose.revisit_boundaries) on a real building: sample11,
// an NYC crop at automatic resolution, decomposed from the paper's own singleton cell (the input's
// labelling depends on the seed of its votes: sample11 is open, and one of its two cells already
// gives the revisited count without revisiting). Without it, each rooftop unit's first cut (upper
// box | lower L-shape) is final and the L needs two more pieces; searching the pieces along that
// boundary together finds two convex parts per unit, as the paper's result has (13 parts at 1e-4).
TEST(Decompose, RevisitingBoundariesOnARealInputGivesFewerPartsAtLowerCost) {
  const fs::path off = test::samples_dir() / "sample11" / "nyc_mn07_crop1.off_reconstruction.off";
  if (!fs::exists(off)) GTEST_SKIP() << "shared samples not found at " << off;
  const PolygonMesh mesh = test::load_off(off.string());
  PreprocessParams pp;  // automatic resolution and up axis, as the sample ships no config
  pp.compute_hausdorff = false;
  auto run_with = [&](bool revisit) {
    const auto deadline = Clock::now() + std::chrono::seconds(120);
    Outcome r{preprocess(mesh, pp, deadline), {}};
    DecomposeParams dp;
    dp.revisit_boundaries = revisit;
    r.dec = decompose(r.pre, dp, deadline);
    return r;
  };
  const Outcome plain = run_with(false);
  const Outcome revisited = run_with(true);
  ASSERT_EQ(revisited.dec.levels.size(), 4u);
  const LevelResult& a = plain.dec.levels.back();
  const LevelResult& b = revisited.dec.levels.back();
  EXPECT_FALSE(revisited.dec.partial);
  EXPECT_LT(b.parts.size(), a.parts.size());
  EXPECT_LE(b.parts.size(), 13u);  // the paper's count
  EXPECT_LT(b.cost, a.cost);
  EXPECT_GE(b.convexity, 0.99);
  expect_valid_levels(revisited, cell_volume(revisited));
  // Same parts with one thread (the revisiting searches run in parallel).
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const Outcome serial = run_with(true);
  ASSERT_EQ(serial.dec.levels.back().parts.size(), b.parts.size());
  for (size_t i = 0; i < b.parts.size(); ++i)
    EXPECT_DOUBLE_EQ(serial.dec.levels.back().parts[i].volume, b.parts[i].volume);
}

// Each part is searched with its own normalisers, so a level can cut nearly convex parts into
// pieces that raise the building's cost. sample22 (a real building, with its config): the finest
// level had 16 parts at cost 1.4848; undoing the cuts that raise the cost where the part put back
// is at least 0.95 convex leaves fewer parts at a lower cost, the building at least cvx_thresh
// convex and no part less convex than before or than 0.95.
TEST(Decompose, CutsThatRaiseTheLevelsCostAreUndone) {
  DecomposeParams off, on;
  off.uncut_convexity = 1.0;
  on.uncut_convexity = 0.95;
  const std::optional<Outcome> kept = run_sample("sample22", off);
  const std::optional<Outcome> undone = run_sample("sample22", on);
  ASSERT_TRUE(kept && undone) << "sample22 not found in " << test::samples_dir();
  ASSERT_EQ(undone->dec.levels.size(), 4u);
  const LevelResult& a = kept->dec.levels.back();
  const LevelResult& b = undone->dec.levels.back();
  EXPECT_LT(b.parts.size(), a.parts.size());
  EXPECT_LT(b.cost, a.cost);
  EXPECT_GE(b.convexity, DecomposeParams{}.cvx_thresh);
  EXPECT_GE(b.min_convexity, std::min(a.min_convexity, 0.95));
  expect_valid_levels(*undone, cell_volume(*undone));
}

// sample16 (a 3D BAG block of 140,000 m³): its first level has more candidate planes than the
// per-part cap of 12, and the best of them are not all among the 12 heaviest. With the opt-in
// first-level cap at 48 the search finds fewer parts at a lower cost in its own objective.
TEST(Decompose, FirstLevelChoosesAmongMoreCandidatePlanes) {
  DecomposeParams capped_params, wide_params;
  capped_params.levels = wide_params.levels = {0.1};
  capped_params.first_level_candidates = -1;  // the default: max_candidates (12)
  wide_params.first_level_candidates = 48;
  const std::optional<Outcome> capped = run_sample("sample16", capped_params);
  const std::optional<Outcome> wide = run_sample("sample16", wide_params);
  ASSERT_TRUE(capped && wide) << "sample16 not found in " << test::samples_dir();
  ASSERT_EQ(wide->dec.levels.size(), 1u);
  const LevelResult& a = capped->dec.levels.front();
  const LevelResult& b = wide->dec.levels.front();
  EXPECT_LT(b.parts.size(), a.parts.size());
  EXPECT_LT(b.cost, a.cost - 0.01);
  expect_valid_levels(*wide, cell_volume(*wide));
}

// A real 3D BAG building (tile 5910, NL.IMBAG.Pand.0503100000018414, LoD2.2, 71 faces; CC BY 4.0
// 3D BAG; coordinates shifted to its first vertex). With cvx_thresh 0.992 the finest level's
// search leaves a 0.03 m³ sliver beside a 365 m³ box. Merged into the neighbour it shares most
// area with, the box's convexity fell to 0.81 and the building's from 0.996 to 0.914 (cost 1.58 ->
// 2.04); merged where the convex hull grows least, the level stays as good as the one before.
TEST(Decompose, TinyPartsMergeWhereTheHullGrowsLeast) {
  const PolygonMesh m =
      test::load_off(std::string(MC_SOURCE_DIR) + "/tests/core/data/3dbag_0503100000018414.off");
  PreprocessParams pp;
  pp.compute_hausdorff = false;
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  Outcome r{preprocess(m, pp, deadline), {}};
  DecomposeParams dp;
  dp.cvx_thresh = 0.992;
  r.dec = decompose(r.pre, dp, deadline);
  ASSERT_EQ(r.dec.levels.size(), 4u);
  const LevelResult& before = r.dec.levels[2];
  const LevelResult& fine = r.dec.levels[3];
  EXPECT_GE(fine.convexity, 0.99);
  EXPECT_LE(fine.cost, before.cost + 1e-9);
  expect_valid_levels(r, cell_volume(r));
}

// Refining one part splits the facets it shares with its neighbours. sample20 (Rockefeller
// Center) showed what happens when a part's space is built before its neighbours are refined:
// the space keeps dead facets, its pieces see boundary edges used once and "pinched vertices",
// and every cut of a 59,000 m³ prism was refused (finest level: convexity 0.9926, worst part
// 0.90). Spaces are now built after the whole level is refined.
TEST(Decompose, PartsAreCutAfterTheirNeighboursAreRefined) {
  int checked = 0;
  for (const auto& s : test::samples()) {
    if (s.name != "sample20") continue;
    PreprocessParams pp = test::paper_params(s);  // and the rest of its config, as bench-samples runs it
    pp.min_points = 100;
    pp.max_points = 10000;
    const auto deadline = Clock::now() + std::chrono::seconds(120);
    Outcome r{preprocess(test::load_off(s.off.string()), pp, deadline), {}};
    DecomposeParams dp;
    dp.max_children = -1;
    r.dec = decompose(r.pre, dp, deadline);
    ASSERT_EQ(r.dec.levels.size(), 4u);
    const LevelResult& fine = r.dec.levels.back();
    EXPECT_FALSE(r.dec.partial);
    // Without the fix: 0.9926 and a worst part of 0.90. With it the worst part moves with the
    // labelling's sample points (0.96 by the point-by-point vote with seed 1; by regions 0.943 at
    // seeds 1-3 and 0.902 at seed 4; with the early stop of mixed cells' votes 0.92, 0.92, 0.943,
    // 0.943), so the convexity of the whole level is the measure and the worst part's bound only
    // sits below what seed 1 gives.
    EXPECT_GE(fine.convexity, 0.995);
    EXPECT_GE(fine.min_convexity, 0.91);
    expect_valid_levels(r, cell_volume(r));
    ++checked;
  }
  EXPECT_EQ(checked, 1);
}

// The level passes share their analyses of whole parts (core/level_work.hpp, LevelAnalyses): a
// part analysed before in the same space is taken from the memo, and is what a fresh analysis
// gives; a part not seen before, or another space, is analysed anew.
TEST(Decompose, LevelPassesShareTheirPartAnalyses) {
  const std::optional<Outcome> r = run_sample("sample22", DecomposeParams{});
  ASSERT_TRUE(r) << "sample22 not found in " << test::samples_dir();
  const CellComplex& cx = *r->pre.complex;
  const LevelResult& last = r->dec.levels.back();
  ASSERT_GE(last.parts.size(), 3u);
  std::vector<level::LevelPart> work;
  for (const PartResult& part : last.parts)
    work.push_back({level::current_leaves(cx, part.cells), part.component});
  const DecomposeParams dp;
  AnalysisContext plain = level::make_context(r->pre, dp, last.lod);
  AnalysisContext memoised = plain;
  LevelAnalyses memo;
  memoised.parts = &memo;
  auto same = [](const PartAnalysis& a, const PartAnalysis& b) {
    EXPECT_EQ(a.bits, b.bits);
    EXPECT_EQ(a.hash, b.hash);
    EXPECT_EQ(a.volume, b.volume);
    EXPECT_EQ(a.hull_volume, b.hull_volume);
    EXPECT_EQ(a.delta, b.delta);
    EXPECT_EQ(a.e_all, b.e_all);
    EXPECT_EQ(a.e_sig, b.e_sig);
    EXPECT_EQ(a.pinch_edges, b.pinch_edges);
    EXPECT_EQ(a.lines.size(), b.lines.size());
    EXPECT_EQ(a.candidates, b.candidates);
  };
  const level::LevelSpace ls(cx, work);
  const auto fresh = level::analyze_parts(ls.space, ls, work, plain);
  const auto first = level::analyze_parts(ls.space, ls, work, memoised);
  EXPECT_EQ(memo.by_part_cells.size(), work.size());
  for (size_t i = 0; i < work.size(); ++i) same(fresh[i], first[i]);
  // The first two parts merged, as the convex merge does: one new analysis, the others reused.
  std::vector<level::LevelPart> merged = work;
  merged[0].cells.insert(merged[0].cells.end(), merged[1].cells.begin(), merged[1].cells.end());
  merged.erase(merged.begin() + 1);
  const level::LevelSpace ls2(cx, merged);  // the same cells, so the same space
  const auto again = level::analyze_parts(ls2.space, ls2, merged, memoised);
  EXPECT_EQ(memo.by_part_cells.size(), work.size() + 1);
  const auto merged_fresh = level::analyze_parts(ls2.space, ls2, merged, plain);
  for (size_t i = 0; i < merged.size(); ++i) same(merged_fresh[i], again[i]);
  // Without the first part the space is another: the memo starts again.
  const std::vector<level::LevelPart> rest(work.begin() + 1, work.end());
  const level::LevelSpace ls3(cx, rest);
  const auto other = level::analyze_parts(ls3.space, ls3, rest, memoised);
  EXPECT_EQ(memo.by_part_cells.size(), rest.size());
  const auto other_fresh = level::analyze_parts(ls3.space, ls3, rest, plain);
  for (size_t i = 0; i < rest.size(); ++i) same(other_fresh[i], other[i]);
}

}  // namespace
}  // namespace mc

namespace mc {
namespace {

// The fidelity measure deferred by preprocess() and run beside the levels
// (decompose_measuring_fidelity) gives the same Hausdorff distances as measured inline, and the
// same levels as decompose() alone (sample3, a real input that is not a valid solid).
TEST(Decompose, FidelityMeasuredBesideTheLevelsIsTheSame) {
  int checked = 0;
  for (const auto& s : test::samples()) {
    if (s.name != "sample3") continue;
    const PolygonMesh in = test::load_off(s.off.string());
    PreprocessParams pp = test::paper_params(s);
    pp.compute_hausdorff = true;
    const auto deadline = Clock::now() + std::chrono::seconds(120);
    Preprocessed inline_pre = preprocess(in, pp, deadline);
    EXPECT_FALSE(inline_pre.pending_fidelity);
    ASSERT_GT(inline_pre.hausdorff, 0);
    Preprocessed deferred = preprocess(in, pp, deadline, std::numeric_limits<double>::quiet_NaN(), true);
    ASSERT_TRUE(deferred.pending_fidelity);
    EXPECT_EQ(deferred.hausdorff, -1);  // not measured yet
    const DecomposeParams dp;
    const Decomposition alone = decompose(inline_pre, dp, deadline);
    const Decomposition beside = decompose_measuring_fidelity(deferred, dp, deadline);
    EXPECT_FALSE(deferred.pending_fidelity);  // released once measured
    EXPECT_EQ(deferred.hausdorff, inline_pre.hausdorff);
    EXPECT_EQ(deferred.hausdorff_in_to_cell, inline_pre.hausdorff_in_to_cell);
    EXPECT_EQ(deferred.hausdorff_cell_to_in, inline_pre.hausdorff_cell_to_in);
    EXPECT_EQ(deferred.mean_distance, inline_pre.mean_distance);
    EXPECT_EQ(deferred.mean_distance_cell_to_in, inline_pre.mean_distance_cell_to_in);
    EXPECT_EQ(deferred.mean_distance_symmetric, inline_pre.mean_distance_symmetric);
    ASSERT_EQ(alone.levels.size(), beside.levels.size());
    for (size_t i = 0; i < alone.levels.size(); ++i) {
      EXPECT_EQ(alone.levels[i].parts.size(), beside.levels[i].parts.size());
      EXPECT_EQ(alone.levels[i].cost, beside.levels[i].cost);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 1);
}

}  // namespace
}  // namespace mc
