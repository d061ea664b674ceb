// Concave lines (docs/algorithm.md §9.3–§9.5), candidate cutting planes (§10) and the
// best-first search (§12) on small prisms whose answers are known in closed form:
// core/part.cpp (analyze_part) and core/search.cpp (search) tested directly, and the
// LoD driver (core/decompose.cpp) at one coarse level.
//
// Every shape is an extruded footprint, 6 high unless said otherwise, preprocessed at cell size
// 0.5 (δ = 0.125), so the singleton cell is the prism exactly. Coordinates in comments are the
// input's; the complex is centred (Preprocessed::offset), so the tests map points with `at()`.
//
// Closed forms used below (weight w = L · D, D the distance along the outward bisector of the
// two faces to the boundary of the part's convex hull, §9.5; A_diag = height × the footprint
// box's diagonal; cost = g + σh with N_max = E_all + 1 and Δ0 = Δ of the root, §11):
//  * L (12 × 12 with a 7 × 7 notch, inner corner (5, 5)): the hull's footprint loses the
//    triangle (12,5)-(5,12)-(12,12) only, so the bisector (1,1)/√2 leaves it on x + y = 17 after
//    D = 7/√2; w = 6 · 7/√2 = 21√2; Δ = (119.5 − 95) · 6 = 147.
//  * U (15 × 12 with a 5 × 7 notch, inner corners (5, 5), (10, 5)): hull = the 15 × 12
//    rectangle; D = 7√2 (to y = 12), w = 42√2 per line; Δ = 35 · 6 = 210.
//  * courtyard ring (16 × 16 around a 6 × 6 courtyard, inner corners (5|11, 5|11)): hull = the
//    16 × 16 square; the bisectors point into the courtyard, D = 11√2, w = 66√2 per line;
//    Δ = 36 · 6 = 216.
// A solution of n convex parts (Σ Δ = 0, Σ E_all = 0, h = 0) costs g = n / N_max + 1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <set>
#include <vector>

#include "buildings.hpp"
#include "cell_grid.hpp"
#include "core/decompose.hpp"
#include "core/part.hpp"
#include "core/preprocess.hpp"
#include "core/search.hpp"

namespace mc {
namespace {

constexpr double kCell = 0.5;
constexpr double kTol = 1e-9;  // geometry of exact, axis-aligned inputs

Preprocessed prep(const PolygonMesh& m) {
  PreprocessParams pp;
  pp.cell_size = kCell;
  pp.dist_thresh = kCell / 4;
  pp.compute_hausdorff = false;
  Preprocessed pre = preprocess(m, pp, Clock::now() + std::chrono::seconds(60));
  EXPECT_EQ(pre.up_axis, 2);
  EXPECT_EQ(pre.components.size(), 1u);
  return pre;
}

// Input coordinates -> complex coordinates (z-up inputs: a translation).
Vec3 at(const Preprocessed& pre, Vec3 p) { return p - pre.offset; }

// The level's analysis settings, as the LoD driver makes them (decompose.cpp, make_context).
AnalysisContext context(const Preprocessed& pre, const DecomposeParams& dp, double level) {
  AnalysisContext ctx;
  ctx.dec = &dp;
  ctx.dist = pre.dist;
  ctx.angle_rad = pre.angle_rad;
  const Vec3 ext = pre.box.hi - pre.box.lo;
  ctx.a_diag = ext.z * std::sqrt(ext.x * ext.x + ext.y * ext.y);
  ctx.level = level;
  ctx.box = pre.box;
  return ctx;
}

// Generated planes are snapped to the pool or registered, as the driver's refinement does.
PlaneResolver registering(Preprocessed& pre, const AnalysisContext& ctx) {
  PlaneRegistry* reg = pre.planes.get();
  return [reg, ctx](const Plane& g, const std::vector<uint32_t>& pool) -> std::optional<uint32_t> {
    return reg->add_snapped(g, pool, ctx.angle_rad, ctx.dist, ctx.box, PlaneOrigin::Candidate);
  };
}

// The whole singleton cell analysed at `level`.
PartAnalysis analyze_cell(Preprocessed& pre, const DecomposeParams& dp, double level) {
  const AnalysisContext ctx = context(pre, dp, level);
  const CellSpace space = make_space(*pre.complex, pre.components[0].cells);
  return analyze_part(space, space.all(), ctx, registering(pre, ctx));
}

// Plane `id` is the plane with normal ±n through point p (complex coordinates).
bool is_plane(const Preprocessed& pre, uint32_t id, Vec3 n, Vec3 p) {
  const Plane& pl = (*pre.planes)[id];
  n = normalized(n);
  return std::abs(std::abs(dot(pl.n, n)) - 1) < kTol && std::abs(pl.signed_distance(p)) < kTol;
}

// The id among `ids` of the plane with normal ±n through p; fails when there is not exactly one.
uint32_t find_plane(const Preprocessed& pre, const std::vector<uint32_t>& ids, Vec3 n, Vec3 p) {
  std::vector<uint32_t> hits;
  for (uint32_t id : ids)
    if (is_plane(pre, id, n, p)) hits.push_back(id);
  EXPECT_EQ(hits.size(), 1u) << "plane n=(" << n.x << "," << n.y << "," << n.z << ") through (" << p.x << ","
                             << p.y << "," << p.z << ")";
  return hits.empty() ? UINT32_MAX : hits[0];
}

// The vertical reflex line at input footprint corner (x, y), z 0..h; returns its index.
size_t expect_vertical_line(const Preprocessed& pre, const PartAnalysis& info, double x, double y, double h,
                            double weight) {
  const Vec3 c = at(pre, {x, y, 0});
  for (size_t i = 0; i < info.lines.size(); ++i) {
    const ConcaveLine& L = info.lines[i];
    const Vec3 off = L.point - c;
    if (std::abs(off.x) > kTol || std::abs(off.y) > kTol) continue;
    SCOPED_TRACE(testing::Message() << "line at (" << x << ", " << y << ")");
    EXPECT_NEAR(std::abs(L.dir.z), 1.0, kTol);
    EXPECT_NEAR(L.length(), h, kTol);
    EXPECT_NEAR(L.angle, 1.5 * M_PI, kTol);  // a right-angled inner corner: 270°
    EXPECT_NEAR(L.weight, weight, kTol * weight);
    // Its two face planes are the walls x = const and y = const through the corner.
    const bool xy = is_plane(pre, L.p1, {1, 0, 0}, c) && is_plane(pre, L.p2, {0, 1, 0}, c);
    const bool yx = is_plane(pre, L.p1, {0, 1, 0}, c) && is_plane(pre, L.p2, {1, 0, 0}, c);
    EXPECT_TRUE(xy || yx);
    return i;
  }
  ADD_FAILURE() << "no concave line at (" << x << ", " << y << ")";
  return 0;
}

std::vector<double> sorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v;
}

void expect_volumes(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  const std::vector<double> a = sorted(got), b = sorted(want);
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-6 * b[i]) << "part " << i;
}

// A root part prepared for a direct search the way the LoD driver prepares one (decompose.cpp,
// refine() and finish()): its cells split by every candidate plane, the side table of each
// candidate, and the root analysed again on the refined space with a lookup-only resolver.
struct SearchRoot {
  DecomposeParams dp;
  PartAnalysis coarse;  // before refinement
  CellSpace space;
  SearchInput input;
  PartAnalysis root;
};

void prepare_root(Preprocessed& pre, double level, SearchRoot& r) {
  CellComplex& cx = *pre.complex;
  const AnalysisContext ctx = context(pre, r.dp, level);
  r.coarse = analyze_cell(pre, r.dp, level);
  std::vector<uint32_t> cells = pre.components[0].cells;
  for (uint32_t plane : r.coarse.candidates) {
    std::vector<uint32_t> next;
    for (uint32_t c : cells) {
      if (auto s = cx.split(c, plane)) {
        next.push_back(s->neg);
        next.push_back(s->pos);
      } else {
        next.push_back(c);
      }
    }
    cells = std::move(next);
  }
  std::sort(cells.begin(), cells.end());
  r.space = make_space(cx, cells);
  r.input.space = &r.space;
  r.input.pool = r.coarse.candidates;
  for (uint32_t plane : r.input.pool) {
    Bits pos(r.space.words(), 0);
    for (uint32_t i = 0; i < cells.size(); ++i)
      if (cx.cell_side(cells[i], plane) > 0) set_bit(pos, i);
    r.input.positive.push_back(std::move(pos));
  }
  r.input.ctx = ctx;
  r.input.deadline = Clock::now() + std::chrono::seconds(60);
  const std::vector<uint32_t> pool = r.input.pool;
  const PlaneRegistry& reg = *pre.planes;
  const PlaneResolver lookup = [&reg, pool, ctx](const Plane& g,
                                                 const std::vector<uint32_t>&) -> std::optional<uint32_t> {
    for (uint32_t id : pool)
      if (same_plane_in_box(g, reg[id], ctx.angle_rad, ctx.dist, ctx.box)) return id;
    return std::nullopt;
  };
  r.root = analyze_part(r.space, r.space.all(), ctx, lookup);
}

// The search's parts tile its root: disjoint cell sets whose union is every cell.
void expect_tiling(const SearchRoot& r, const SearchResult& res) {
  Bits seen(r.space.words(), 0);
  for (const PartAnalysis& p : res.parts)
    for (size_t w = 0; w < seen.size(); ++w) {
      EXPECT_EQ(seen[w] & p.bits[w], 0u);
      seen[w] |= p.bits[w];
    }
  EXPECT_EQ(seen, r.space.all());
}

Decomposition decompose_at(Preprocessed& pre, std::vector<double> levels) {
  DecomposeParams dp;
  dp.levels = std::move(levels);
  return decompose(pre, dp, Clock::now() + std::chrono::seconds(60));
}

std::vector<double> part_volumes(const LevelResult& level) {
  std::vector<double> v;
  for (const PartResult& p : level.parts) v.push_back(p.volume);
  return v;
}

void expect_convex_parts(const LevelResult& level) {
  for (const PartResult& p : level.parts) {
    EXPECT_GE(p.convexity, 0.99);
    EXPECT_NEAR(p.convexity, 1.0, kTol);  // every part here is a convex prism
  }
}

// ---------------------------------------------------------------------------------------------
// Concave lines and candidate planes (analyze_part)

// A part's cells are visited a word at a time (core/part.hpp): the set bits, ascending, across
// word boundaries and up to the last bit of the last word.
TEST(PartBits, ForEachBitVisitsTheSetBitsAscending) {
  Bits bits(3, 0);
  const std::vector<uint32_t> set = {0, 5, 63, 64, 100, 127, 130, 191};
  for (uint32_t i : set) set_bit(bits, i);
  std::vector<uint32_t> seen;
  for_each_bit(bits, [&](uint32_t i) { seen.push_back(i); });
  EXPECT_EQ(seen, set);
  seen.clear();
  for_each_bit(Bits(2, 0), [&](uint32_t i) { seen.push_back(i); });
  EXPECT_TRUE(seen.empty());
}

// A roof apex where 24 faces meet: the analysis groups a part's edge uses by their first vertex
// (core/key_order.hpp). Every edge must still have its two uses: a convex solid, no pinch, no line.
TEST(ConcaveLines, ConeRoofApexOfManyFacesIsConvexWithoutPinches) {
  PolygonMesh m;
  const int n = 24;
  std::vector<std::pair<double, double>> ring;
  for (int i = 0; i < n; ++i)
    ring.emplace_back(6 + 6 * std::cos(2 * M_PI * i / n), 6 + 6 * std::sin(2 * M_PI * i / n));
  test::add_prism(m, ring, 0, 6);
  m.faces.pop_back();  // the flat top: a cone roof instead
  const uint32_t apex = static_cast<uint32_t>(m.vertices.size());
  m.vertices.push_back({6, 6, 10});
  for (uint32_t i = 0; i < static_cast<uint32_t>(n); ++i)
    m.faces.push_back({{{static_cast<uint32_t>(n) + i, static_cast<uint32_t>(n) + (i + 1) % n, apex}},
                       m.label_index("RoofSurface")});
  Preprocessed pre = prep(m);
  DecomposeParams dp;
  const PartAnalysis a = analyze_cell(pre, dp, 0.01);
  EXPECT_EQ(a.pinch_edges, 0);
  EXPECT_NEAR(a.hull_volume, a.volume, 1e-9 * a.volume);
  EXPECT_EQ(a.e_all, 0);
  EXPECT_GT(a.volume, 0.9 * (M_PI * 36 * 6 + M_PI * 36 * 4 / 3));  // the 24-gon's cylinder and cone
}

TEST(ConcaveLines, BoxHasNoConcaveLineAndNoCandidate) {
  Preprocessed pre = prep(test::box_building());  // 10 × 6 × 5
  const DecomposeParams dp;
  const PartAnalysis info = analyze_cell(pre, dp, 0.0001);
  EXPECT_NEAR(info.volume, 300.0, 1e-6 * 300);
  EXPECT_NEAR(info.hull_volume, 300.0, 1e-6 * 300);
  EXPECT_EQ(info.delta, 0.0);  // exactly convex parts have Δ exactly 0 (§9.2)
  EXPECT_FALSE(info.nearly_convex);
  EXPECT_EQ(info.e_all, 0);
  EXPECT_EQ(info.e_sig, 0);
  EXPECT_TRUE(info.lines.empty());
  EXPECT_TRUE(info.candidates.empty());
  EXPECT_EQ(info.pinch_edges, 0);
}

// Pinched vertices and edges of a part (docs/algorithm.md §9.2) on a 3 × 3 × 3 grid of unit
// cells: the fan test runs only when the Euler count V − E + F = 2 per component fails, so a
// ring (genus 1) and two cubes meeting at a corner both go through it, and a box does not.
TEST(ConcaveLines, PinchedVerticesCountedWhereTheEulerCountFails) {
  PlaneRegistry reg;
  BBox box;
  box.add({0, 0, 0});
  box.add({3, 3, 3});
  CellComplex cx(reg, box);
  test::split_into_unit_cells(cx, reg, 3);
  const std::vector<uint32_t> all = cx.live_cells();
  ASSERT_EQ(all.size(), 27u);
  auto cell_at = [&](int x, int y, int z) {
    for (uint32_t c : all) {
      const Vec3 m = cx.cell_centroid(c);
      if (std::abs(m.x - x - 0.5) < 0.1 && std::abs(m.y - y - 0.5) < 0.1 && std::abs(m.z - z - 0.5) < 0.1)
        return c;
    }
    ADD_FAILURE() << "no cell at " << x << y << z;
    return CellComplex::kNone;
  };
  const DecomposeParams dp;
  AnalysisContext ctx;
  ctx.dec = &dp;
  ctx.dist = 0.01;
  ctx.a_diag = 3 * std::sqrt(18.0);
  ctx.level = 0.1;
  ctx.box = box;
  const PlaneResolver none = [](const Plane&, const std::vector<uint32_t>&) {
    return std::optional<uint32_t>();
  };
  auto pinches = [&](std::vector<uint32_t> cells) {
    std::sort(cells.begin(), cells.end());
    const CellSpace space = make_space(cx, cells);
    return analyze_part(space, space.all(), ctx, none).pinch_edges;
  };
  EXPECT_EQ(pinches(all), 0);                                   // a box: V − E + F = 2
  EXPECT_EQ(pinches({cell_at(0, 0, 0), cell_at(2, 2, 2)}), 0);  // apart: 2 per component
  EXPECT_EQ(pinches({cell_at(0, 0, 0), cell_at(1, 1, 1)}), 1);  // a pinched vertex
  EXPECT_EQ(pinches({cell_at(0, 0, 0), cell_at(1, 1, 0)}), 3);  // a pinch edge and its two ends
  std::vector<uint32_t> ring;                                   // genus 1 (V − E + F = 0), not pinched
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      if (x != 1 || y != 1) ring.push_back(cell_at(x, y, 0));
  EXPECT_EQ(pinches(ring), 0);
  // A part whose boundary has no reflex edge is its own hull, but only when that boundary is one
  // surface: two cubes apart have the hull of both (the root of a building of two components).
  auto analysed = [&](std::vector<uint32_t> cells) {
    std::sort(cells.begin(), cells.end());
    const CellSpace space = make_space(cx, cells);
    return analyze_part(space, space.all(), ctx, none);
  };
  const PartAnalysis cube = analysed({cell_at(1, 1, 1)});
  EXPECT_EQ(cube.hull_volume, cube.volume);
  EXPECT_EQ(cube.delta, 0.0);
  const PartAnalysis apart = analysed({cell_at(0, 0, 0), cell_at(2, 2, 2)});
  EXPECT_NEAR(apart.volume, 2.0, 1e-12);
  EXPECT_NEAR(apart.hull_volume, 7.0, 1e-9);  // a unit cube swept by (2, 2, 2): 1 + 2 + 2 + 2
  EXPECT_GT(apart.delta, 0.0);
}

TEST(ConcaveLines, LShapeHasOneLineAtTheInnerCornerProposingBothWallsAndTheBisector) {
  Preprocessed pre = prep(test::l_building());
  const DecomposeParams dp;
  const size_t planes_before = pre.planes->size();
  const PartAnalysis info = analyze_cell(pre, dp, 0.1);
  EXPECT_NEAR(info.volume, 570.0, 1e-6 * 570);
  EXPECT_NEAR(info.hull_volume, 717.0, 1e-6 * 717);
  EXPECT_NEAR(info.delta, 147.0, 1e-6 * 147);
  EXPECT_EQ(info.pinch_edges, 0);
  ASSERT_EQ(info.lines.size(), 1u);
  EXPECT_EQ(info.e_all, 1);
  EXPECT_EQ(info.e_sig, 1);  // w / A_diag = 21√2 / (6 · 12√2) = 0.29 >= 0.1
  expect_vertical_line(pre, info, 5, 5, 6, 21 * std::sqrt(2.0));
  // Candidates: both wall planes through the line (same weight: region ids first, by id), then
  // the bisector through the material (V–V line, with_bisector), newly registered.
  const Vec3 c = at(pre, {5, 5, 0});
  ASSERT_EQ(info.candidates.size(), 3u);
  const std::set<uint32_t> walls{info.candidates[0], info.candidates[1]};
  EXPECT_EQ(walls, (std::set<uint32_t>{info.lines[0].p1, info.lines[0].p2}));
  EXPECT_LT(info.candidates[0], info.candidates[1]);
  EXPECT_TRUE(is_plane(pre, info.candidates[2], {1, -1, 0}, c));
  EXPECT_EQ(pre.planes->origin(info.candidates[2]), PlaneOrigin::Candidate);
  EXPECT_EQ(pre.planes->size(), planes_before + 1);
}

TEST(ConcaveLines, LShapeCandidatesFollowWithBisectorAndCutMode) {
  {
    Preprocessed pre = prep(test::l_building());
    DecomposeParams dp;
    dp.with_bisector = false;
    const PartAnalysis info = analyze_cell(pre, dp, 0.1);
    ASSERT_EQ(info.lines.size(), 1u);
    EXPECT_EQ(std::set<uint32_t>(info.candidates.begin(), info.candidates.end()),
              (std::set<uint32_t>{info.lines[0].p1, info.lines[0].p2}));
    EXPECT_EQ(info.candidates.size(), 2u);
  }
  {
    Preprocessed pre = prep(test::l_building());
    DecomposeParams dp;
    dp.cut_mode = "H";  // horizontal planes only: every candidate of a vertical corner is vertical
    const PartAnalysis info = analyze_cell(pre, dp, 0.1);
    EXPECT_EQ(info.e_sig, 1);
    EXPECT_TRUE(info.candidates.empty());
  }
  {
    Preprocessed pre = prep(test::l_building());
    DecomposeParams dp;
    dp.max_candidates = 1;
    const PartAnalysis info = analyze_cell(pre, dp, 0.1);
    ASSERT_EQ(info.candidates.size(), 1u);
    EXPECT_EQ(info.candidates[0], std::min(info.lines[0].p1, info.lines[0].p2));
  }
}

TEST(ConcaveLines, UShapeHasTwoLinesAndTheSharedWallIsTheHeaviestCandidate) {
  Preprocessed pre = prep(test::u_building());
  const DecomposeParams dp;
  const PartAnalysis info = analyze_cell(pre, dp, 0.1);
  EXPECT_NEAR(info.volume, 870.0, 1e-6 * 870);
  EXPECT_NEAR(info.delta, 210.0, 1e-6 * 210);
  ASSERT_EQ(info.lines.size(), 2u);
  EXPECT_EQ(info.e_all, 2);
  EXPECT_EQ(info.e_sig, 2);
  const double w = 42 * std::sqrt(2.0);
  const size_t a = expect_vertical_line(pre, info, 5, 5, 6, w);
  const size_t b = expect_vertical_line(pre, info, 10, 5, 6, w);
  EXPECT_NE(a, b);
  // Candidates: the notch's back wall y = 5 is proposed by both lines (weight 2w, first), then
  // the walls x = 5, x = 10 and the two bisectors x − y = 0 and x + y = 15 (weight w each).
  ASSERT_EQ(info.candidates.size(), 5u);
  const Vec3 c5 = at(pre, {5, 5, 0}), c10 = at(pre, {10, 5, 0});
  EXPECT_TRUE(is_plane(pre, info.candidates[0], {0, 1, 0}, c5));
  find_plane(pre, info.candidates, {1, 0, 0}, c5);
  find_plane(pre, info.candidates, {1, 0, 0}, c10);
  const uint32_t bis5 = find_plane(pre, info.candidates, {1, -1, 0}, c5);
  const uint32_t bis10 = find_plane(pre, info.candidates, {1, 1, 0}, c10);
  EXPECT_NE(bis5, bis10);
}

TEST(ConcaveLines, CourtyardRingHasFourLinesAtTheInnerCorners) {
  Preprocessed pre = prep(test::courtyard_building());
  const DecomposeParams dp;
  const PartAnalysis info = analyze_cell(pre, dp, 0.1);
  EXPECT_NEAR(info.volume, 1320.0, 1e-6 * 1320);
  EXPECT_NEAR(info.hull_volume, 1536.0, 1e-6 * 1536);
  EXPECT_NEAR(info.delta, 216.0, 1e-6 * 216);
  EXPECT_EQ(info.pinch_edges, 0);
  ASSERT_EQ(info.lines.size(), 4u);
  EXPECT_EQ(info.e_all, 4);
  EXPECT_EQ(info.e_sig, 4);
  const double w = 66 * std::sqrt(2.0);
  std::set<size_t> seen;
  for (double x : {5.0, 11.0})
    for (double y : {5.0, 11.0}) seen.insert(expect_vertical_line(pre, info, x, y, 6, w));
  EXPECT_EQ(seen.size(), 4u);
  // Six candidates, each proposed by two lines: the four courtyard walls, and the two diagonals
  // of the (centred) square, each the bisector of two opposite corners (the second snaps to the
  // first, §10).
  ASSERT_EQ(info.candidates.size(), 6u);
  const Vec3 lo = at(pre, {5, 5, 0}), hi = at(pre, {11, 11, 0});
  find_plane(pre, info.candidates, {1, 0, 0}, lo);
  find_plane(pre, info.candidates, {0, 1, 0}, lo);
  find_plane(pre, info.candidates, {1, 0, 0}, hi);
  find_plane(pre, info.candidates, {0, 1, 0}, hi);
  const uint32_t d1 = find_plane(pre, info.candidates, {1, -1, 0}, lo);
  EXPECT_TRUE(is_plane(pre, d1, {1, -1, 0}, hi));
  const uint32_t d2 = find_plane(pre, info.candidates, {1, 1, 0}, at(pre, {11, 5, 0}));
  EXPECT_TRUE(is_plane(pre, d2, {1, 1, 0}, at(pre, {5, 11, 0})));
}

// A 4 × 4 × 8 tower on a 10 × 10 × 4 podium: four horizontal H–V lines (§10, T4: no generated
// plane) where the tower meets the terrace. Bisector (−1, 0, 1)/√2 from the line at x = 3
// reaches the hull's side facet 8x − 3z + 12 = 0 after D = 24√2/11, so w = 4 · 24√2/11 ≈ 12.34,
// below 0.1 · A_diag (12 · 10√2 ≈ 169.7, 7.3 %): the setback counts only from level 0.01 on.
TEST(ConcaveLines, SetbackLinesAreSignificantOnlyAtTheFinerLevel) {
  Preprocessed pre = prep(test::stepped_tower());
  const DecomposeParams dp;
  const size_t planes_before = pre.planes->size();
  const PartAnalysis coarse = analyze_cell(pre, dp, 0.1);
  EXPECT_NEAR(coarse.volume, 528.0, 1e-6 * 528);
  EXPECT_NEAR(coarse.hull_volume, 816.0, 1e-6 * 816);  // the box and a frustum 8/3 (100 + 16 + 40)
  ASSERT_EQ(coarse.lines.size(), 4u);
  EXPECT_EQ(coarse.e_all, 4);
  EXPECT_EQ(coarse.e_sig, 0);
  EXPECT_TRUE(coarse.candidates.empty());
  const double w = 4 * 24 * std::sqrt(2.0) / 11;
  for (const ConcaveLine& L : coarse.lines) {
    EXPECT_NEAR(L.dir.z, 0.0, kTol);  // horizontal
    EXPECT_NEAR(L.length(), 4.0, kTol);
    EXPECT_NEAR(L.angle, 1.5 * M_PI, kTol);
    EXPECT_NEAR(L.weight, w, kTol * w);
  }
  const PartAnalysis fine = analyze_cell(pre, dp, 0.01);
  EXPECT_EQ(fine.e_sig, 4);
  // The terrace (proposed by all four lines) first, then the four tower walls; nothing generated.
  ASSERT_EQ(fine.candidates.size(), 5u);
  EXPECT_TRUE(is_plane(pre, fine.candidates[0], {0, 0, 1}, at(pre, {0, 0, 4})));
  find_plane(pre, fine.candidates, {1, 0, 0}, at(pre, {3, 0, 0}));
  find_plane(pre, fine.candidates, {1, 0, 0}, at(pre, {7, 0, 0}));
  find_plane(pre, fine.candidates, {0, 1, 0}, at(pre, {0, 3, 0}));
  find_plane(pre, fine.candidates, {0, 1, 0}, at(pre, {0, 7, 0}));
  EXPECT_EQ(pre.planes->size(), planes_before);
}

// ---------------------------------------------------------------------------------------------
// The search (core/search.hpp), called directly on a prepared root

struct SearchCase {
  const char* name;
  PolygonMesh (*mesh)();
  int lines;                    // E_all of the root: N_max = lines + 1
  std::vector<double> volumes;  // the parts found
  int64_t expanded;
};
void PrintTo(const SearchCase& c, std::ostream* os) { *os << c.name; }

class DirectSearchKnownAnswer : public testing::TestWithParam<SearchCase> {};

// L: one cut by a wall plane (the first candidate) leaves two convex parts, 360 and 210:
// g = 2/2 + 1 = 2. U: the shared wall y = 5 cuts the U into three pieces at once (the bar and
// both prongs): g = 3/3 + 1 = 2, found at the first expansion. Courtyard ring: four convex parts
// are the fewest (the middles of the four wings, e.g. (8, 2.5) and (13.5, 8), see one another
// only through the courtyard, so no convex piece holds two of them) and no single plane gets
// there: the objective prices every 4-part convex solution alike, g = 4/5 + 1 = 1.8; which one
// comes out is the search's tie-break (see CoarseLevel.CourtyardRingGivesFourConvexParts).
// Expansions: L and U find their solution among the root's children (1); the ring needs the
// root and its first child (2), after which every open node costs at least the 1.8 found.
TEST_P(DirectSearchKnownAnswer, FindsTheConvexDecompositionTheObjectiveImplies) {
  const SearchCase& sc = GetParam();
  Preprocessed pre = prep(sc.mesh());
  SearchRoot r;
  prepare_root(pre, 0.1, r);
  // Refinement splits cells, not the part's surface: the same lines, Δ and candidates.
  EXPECT_EQ(r.root.e_all, sc.lines);
  EXPECT_EQ(r.root.e_sig, sc.lines);
  EXPECT_EQ(r.root.e_all, r.coarse.e_all);
  EXPECT_NEAR(r.root.volume, r.coarse.volume, 1e-9 * r.coarse.volume);
  EXPECT_NEAR(r.root.delta, r.coarse.delta, 1e-9 * r.coarse.delta);
  EXPECT_EQ(r.root.candidates, r.coarse.candidates);
  EXPECT_GT(r.space.cells.size(), pre.components[0].cells.size());

  const SearchResult res = search(r.input, r.root);
  EXPECT_FALSE(res.deadline_hit);
  EXPECT_FALSE(res.budget_hit);
  EXPECT_EQ(res.expanded, sc.expanded);
  ASSERT_EQ(res.parts.size(), sc.volumes.size());
  const double n_max = sc.lines + 1;
  EXPECT_NEAR(res.g, sc.volumes.size() / n_max + 1, 1e-12);
  EXPECT_EQ(res.h, 0.0);
  EXPECT_NEAR(res.cost, res.g, 1e-12);
  std::vector<double> vols;
  for (const PartAnalysis& p : res.parts) {
    vols.push_back(p.volume);
    EXPECT_EQ(p.e_all, 0);
    EXPECT_EQ(p.delta, 0.0);
    EXPECT_NEAR(p.convexity(), 1.0, kTol);
    EXPECT_EQ(p.pinch_edges, 0);
  }
  expect_volumes(vols, sc.volumes);
  expect_tiling(r, res);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, DirectSearchKnownAnswer,
    testing::Values(SearchCase{"L", &test::l_building, 1, {360, 210}, 1},
                    SearchCase{"U", &test::u_building, 2, {450, 210, 210}, 1},
                    SearchCase{"CourtyardRing", &test::courtyard_building, 4, {405, 405, 255, 255}, 2}),
    [](const testing::TestParamInfo<SearchCase>& i) { return std::string(i.param.name); });

// A cut by an unbounded candidate splits the whole part into its connected pieces on each side
// (§10, §12.2): the U's bisector x − y = 0 through the inner corner (5, 5) crosses the empty
// notch and cuts the corner (10, 10)-(10, 12)-(12, 12) off the other prong: three pieces,
// 47.5 · 6 = 285 (convex), 2 · 6 = 12 (convex) and the rest, 573, still concave at (10, 5).
TEST(DirectSearch, BisectorOfTheUCutsOffACornerOfTheOtherProng) {
  Preprocessed pre = prep(test::u_building());
  SearchRoot r;
  prepare_root(pre, 0.1, r);
  const uint32_t bis = find_plane(pre, r.input.pool, {1, -1, 0}, at(pre, {5, 5, 0}));
  const size_t k = std::find(r.input.pool.begin(), r.input.pool.end(), bis) - r.input.pool.begin();
  ASSERT_LT(k, r.input.pool.size());
  const Bits all = r.space.all();
  Bits pos(all.size()), neg(all.size());
  for (size_t w = 0; w < all.size(); ++w) {
    pos[w] = all[w] & r.input.positive[k][w];
    neg[w] = all[w] & ~r.input.positive[k][w];
  }
  const PlaneResolver none = [](const Plane&, const std::vector<uint32_t>&) {
    return std::optional<uint32_t>{};
  };
  std::vector<double> convex, concave;
  for (const Bits* side : {&pos, &neg})
    for (Bits& piece : components(r.space, *side)) {
      const PartAnalysis p = analyze_part(r.space, std::move(piece), r.input.ctx, none);
      (p.e_all == 0 ? convex : concave).push_back(p.volume);
      if (p.e_all > 0) {
        EXPECT_EQ(p.e_all, 1);
        expect_vertical_line(pre, p, 10, 5, 6, p.lines[0].weight);
      }
    }
  expect_volumes(convex, {285, 12});
  expect_volumes(concave, {573});
}

// σ = 1 (the paper's "optimal", admissible search) finds solutions of the same cost.
TEST(DirectSearch, OptimalSearchAgreesOnTheUShape) {
  Preprocessed pre = prep(test::u_building());
  SearchRoot r;
  r.dp.sigma = 1;
  prepare_root(pre, 0.1, r);
  const SearchResult res = search(r.input, r.root);
  ASSERT_EQ(res.parts.size(), 3u);
  EXPECT_NEAR(res.cost, 2.0, 1e-12);
  std::vector<double> vols;
  for (const PartAnalysis& p : res.parts) vols.push_back(p.volume);
  expect_volumes(vols, {450, 210, 210});
  expect_tiling(r, res);
}

// A root without a significant line has nothing to search: the root itself comes back.
TEST(DirectSearch, ConvexRootIsReturnedWhole) {
  Preprocessed pre = prep(test::box_building());
  SearchRoot r;
  prepare_root(pre, 0.1, r);
  EXPECT_TRUE(r.root.candidates.empty());
  const SearchResult res = search(r.input, r.root);
  ASSERT_EQ(res.parts.size(), 1u);
  EXPECT_EQ(res.expanded, 0);
  EXPECT_NEAR(res.parts[0].volume, 300.0, 1e-6 * 300);
  // N_max = 1 and Δ0 = 1 (Δ of a convex root is 0, §11.2): g = 1/1 + (1 − 0)/1 = 2, h = 0.
  EXPECT_NEAR(res.cost, 2.0, 1e-12);
  EXPECT_EQ(res.h, 0.0);
}

// ---------------------------------------------------------------------------------------------
// The LoD driver at one coarse level (decompose)

TEST(CoarseLevel, BoxStaysOnePart) {
  Preprocessed pre = prep(test::box_building());
  const Decomposition d = decompose_at(pre, {0.1});
  EXPECT_EQ(d.concave_edges, 0);
  ASSERT_EQ(d.levels.size(), 1u);
  expect_volumes(part_volumes(d.levels[0]), {300});
  expect_convex_parts(d.levels[0]);
}

TEST(CoarseLevel, LShapeGivesTwoParts) {
  Preprocessed pre = prep(test::l_building());
  const Decomposition d = decompose_at(pre, {0.1});
  EXPECT_EQ(d.concave_edges, 1);
  ASSERT_EQ(d.levels.size(), 1u);
  const LevelResult& l = d.levels[0];
  expect_volumes(part_volumes(l), {360, 210});  // 360 + 210 = 570, the L's volume
  expect_convex_parts(l);
  EXPECT_EQ(l.remaining_concave, 0);
  // Whole-building normalisers (§11.3): N_max = 2, Δ0 = Δ(L) = 147.
  EXPECT_NEAR(l.cost, 2.0, 1e-9);
  ASSERT_EQ(l.parts[0].neighbours, std::vector<uint32_t>{1});
  ASSERT_EQ(l.parts[1].neighbours, std::vector<uint32_t>{0});
}

TEST(CoarseLevel, UShapeGivesThreeParts) {
  Preprocessed pre = prep(test::u_building());
  const Decomposition d = decompose_at(pre, {0.1});
  EXPECT_EQ(d.concave_edges, 2);
  ASSERT_EQ(d.levels.size(), 1u);
  const LevelResult& l = d.levels[0];
  expect_volumes(part_volumes(l), {450, 210, 210});
  expect_convex_parts(l);
  EXPECT_NEAR(l.cost, 2.0, 1e-9);
}

// Four convex parts are the fewest for a ring around a courtyard (DirectSearch above), and the
// objective prefers them to anything fewer and concave: with N_max = 5, Δ0 = 216, σ = 2, k = 4,
// cost = n/5 + 1 + ΣΔ/216 + ΣE_all/10, so 4 convex parts cost 1.8, while a node keeping a
// concave piece costs more (three parts and one L left: 1.7 + 108/216 = 2.2; every concave
// piece here misses at least an 18 m² triangle of its hull, Δ >= 108).
// Which 4-part solution: the first cut ties exactly in the objective between a courtyard wall
// (a 480 bar and a U, Δ 216, two lines) and a diagonal (two Ls, Δ 108 and one line each): both
// change the cost by 0. The diagonal wins on rounding alone (its pieces' Δ come out as
// 107.99999999999989, a cost change of −8.9e-16 against +2.2e-16), not on the candidate order
// (walls first: equal weight 2w, lower plane ids). Each L is then cut at its reflex corner by a
// courtyard wall (again an exact tie with the other diagonal, broken by plane id), so the ring
// comes out as a pinwheel of trapezoids: two of (16 + 11)/2 · 5 · 6 = 405 and two of
// (11 + 6)/2 · 5 · 6 = 255. The other 4-part solutions (bars 480, 480 and stubs 180, 180; four
// diagonal trapezoids of 330) cost the same: a change here moves the tie-break, not the optimum.
TEST(CoarseLevel, CourtyardRingGivesFourConvexParts) {
  Preprocessed pre = prep(test::courtyard_building());
  const Decomposition d = decompose_at(pre, {0.1});
  EXPECT_EQ(d.concave_edges, 4);
  ASSERT_EQ(d.levels.size(), 1u);
  const LevelResult& l = d.levels[0];
  expect_volumes(part_volumes(l), {405, 405, 255, 255});
  expect_convex_parts(l);
  EXPECT_NEAR(l.cost, 1.8, 1e-9);
  EXPECT_FALSE(l.truncated);
}

}  // namespace
}  // namespace mc
