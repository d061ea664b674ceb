#include "core/complex.hpp"
#include "core/carve.hpp"
#include "core/surface.hpp"

#include "cell_grid.hpp"

#include <gtest/gtest.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <map>
#include <random>

namespace mc {
namespace {

BBox unit_box(double s = 1.0) {
  BBox b;
  b.add({0, 0, 0});
  b.add({s, s, s});
  return b;
}

// Every live cell is closed: each directed edge of its outward loops has its reverse.
void expect_cells_closed(const CellComplex& cx) {
  for (uint32_t c : cx.live_cells()) {
    std::map<std::pair<uint32_t, uint32_t>, int> edges;
    for (uint32_t f : cx.cell(c).facets) {
      ASSERT_TRUE(cx.facet(f).alive);
      ASSERT_TRUE(cx.facet(f).front == c || cx.facet(f).back == c);
      const auto loop = cx.outward_loop(f, c);
      for (size_t i = 0; i < loop.size(); ++i) edges[{loop[i], loop[(i + 1) % loop.size()]}]++;
    }
    for (const auto& [e, n] : edges) {
      EXPECT_EQ(n, 1);
      EXPECT_EQ(edges.count({e.second, e.first}), 1u) << "cell " << c << " open at edge";
    }
    EXPECT_GT(cx.cell_volume(c), 0);
  }
}

// Conformity: every live facet appears in the facet lists of both of its cells.
void expect_facets_shared(const CellComplex& cx) {
  for (uint32_t f = 0; f < cx.num_facets(); ++f) {
    const auto& fa = cx.facet(f);
    if (!fa.alive) continue;
    for (uint32_t c : {fa.front, fa.back}) {
      if (c == CellComplex::kNone) continue;
      const auto& fs = cx.cell(c).facets;
      EXPECT_NE(std::find(fs.begin(), fs.end(), f), fs.end());
    }
  }
}

double total_volume(const CellComplex& cx) {
  double v = 0;
  for (uint32_t c : cx.live_cells()) v += cx.cell_volume(c);
  return v;
}

// A 3 x 3 x 3 grid of cells with every cell inside except the centre: the centre is a cavity
// (it cannot reach the box boundary through outside cells) and is filled; a corner is not.
TEST(Carve, EnclosedOutsideCellsAreFilled) {
  PlaneRegistry reg;
  CellComplex cx(reg, unit_box(3));
  test::split_into_unit_cells(cx, reg, 3);
  ASSERT_EQ(cx.live_cells().size(), 27u);
  uint32_t centre = CellComplex::kNone, corner = CellComplex::kNone;
  std::vector<uint32_t> inside;
  for (uint32_t c : cx.live_cells()) {
    const Vec3 m = cx.cell_centroid(c);
    if (std::abs(m.x - 1.5) < 0.1 && std::abs(m.y - 1.5) < 0.1 && std::abs(m.z - 1.5) < 0.1) centre = c;
    else if (m.x < 1 && m.y < 1 && m.z < 1) corner = c;
    else inside.push_back(c);
  }
  ASSERT_NE(centre, CellComplex::kNone);
  ASSERT_NE(corner, CellComplex::kNone);
  double filled = 0;
  EXPECT_EQ(fill_cavities(cx, inside, filled), 1u);
  EXPECT_NEAR(filled, 1.0, 1e-12);
  EXPECT_TRUE(std::binary_search(inside.begin(), inside.end(), centre));
  EXPECT_FALSE(std::binary_search(inside.begin(), inside.end(), corner));
}

// Four 2 x 2 x 4 columns around the vertical edge x = y = 2 of the box [0, 4]³, the two
// diagonal ones inside: a pinch edge whose cheapest repair flips a whole column (16). With
// carving planes beside the edge (x = 1.5, 2.5 and y = 1.5, 2.5) and cuts allowed beyond a flip
// of 1, the column along the edge is cut down to a 0.5 x 0.5 x 4 piece, and that one flips.
TEST(Carve, APinchIsRepairedByAPieceAlongItsEdge) {
  auto setup = [](PlaneRegistry& reg, CellComplex& cx, std::vector<CarvePlane>& planes,
                  std::vector<uint32_t>& inside) {
    const uint32_t x2 = reg.add({{1, 0, 0}, -2}), y2 = reg.add({{0, 1, 0}, -2});
    for (uint32_t pl : {x2, y2})
      for (uint32_t c : cx.live_cells()) cx.split(c, pl);
    for (uint32_t c : cx.live_cells()) {
      const Vec3 m = cx.cell_centroid(c);
      if ((m.x < 2) == (m.y < 2)) inside.push_back(c);
    }
    std::sort(inside.begin(), inside.end());
    for (const Plane& pl :
         {Plane{{1, 0, 0}, -1.5}, Plane{{1, 0, 0}, -2.5}, Plane{{0, 1, 0}, -1.5}, Plane{{0, 1, 0}, -2.5}})
      planes.push_back({reg.add(pl), unit_box(4)});
  };
  auto pinch_edges = [](const CellComplex& cx, const std::vector<uint32_t>& inside) {
    size_t n = 0;
    for (const auto& [e, uses] : boundary_edge_uses(cx, inside)) n += uses.size() > 2;
    return n;
  };
  {  // without cuts: a whole column changes side
    PlaneRegistry reg;
    CellComplex cx(reg, unit_box(4));
    std::vector<CarvePlane> planes;
    std::vector<uint32_t> inside;
    setup(reg, cx, planes, inside);
    ASSERT_EQ(pinch_edges(cx, inside), 1u);
    double flipped = 0;
    EXPECT_EQ(remove_pinch_edges(cx, inside, flipped), 1u);
    EXPECT_NEAR(flipped, 16.0, 1e-9);
    EXPECT_EQ(pinch_edges(cx, inside), 0u);
  }
  PlaneRegistry reg;
  CellComplex cx(reg, unit_box(4));
  std::vector<CarvePlane> planes;
  std::vector<uint32_t> inside;
  setup(reg, cx, planes, inside);
  CarveParams p;
  p.dist = 0.1;
  PinchCuts cuts;
  cuts.planes = &planes;
  cuts.params = &p;
  cuts.outer = unit_box(4);
  cuts.max_flip = 1.0;
  std::vector<float> share;
  double flipped = 0;
  EXPECT_EQ(remove_pinch_edges(cx, inside, flipped, share, cuts), 1u);
  EXPECT_NEAR(flipped, 1.0, 1e-9);
  EXPECT_EQ(pinch_edges(cx, inside), 0u);
  EXPECT_TRUE(std::is_sorted(inside.begin(), inside.end()));
  double in = 0;
  for (uint32_t c : inside) in += cx.cell_volume(c);
  EXPECT_NEAR(std::abs(in - 32.0), 1.0, 1e-9);  // the cut pieces kept their labels
}

TEST(CellComplex, BoxCellIsClosedWithUnitVolume) {
  PlaneRegistry reg;
  CellComplex cx(reg, unit_box());
  EXPECT_EQ(cx.live_cells().size(), 1u);
  EXPECT_NEAR(cx.cell_volume(0), 1.0, 1e-12);
  expect_cells_closed(cx);
}

TEST(CellComplex, SplitByMidPlaneHalvesTheBox) {
  PlaneRegistry reg;
  CellComplex cx(reg, unit_box());
  const uint32_t p = reg.add({{1, 0, 0}, -0.5});
  auto r = cx.split(0, p);
  ASSERT_TRUE(r);
  EXPECT_NEAR(cx.cell_volume(r->neg), 0.5, 1e-12);
  EXPECT_NEAR(cx.cell_volume(r->pos), 0.5, 1e-12);
  EXPECT_LT(cx.cell_centroid(r->neg).x, 0.5);
  EXPECT_GT(cx.cell_centroid(r->pos).x, 0.5);
  expect_cells_closed(cx);
  // A plane through a face or outside does not split.
  EXPECT_FALSE(cx.split(r->neg, reg.add({{1, 0, 0}, 0.0})));
  EXPECT_FALSE(cx.split(r->neg, p));
}

TEST(CellComplex, SplitThroughVerticesAndEdgesStaysExact) {
  PlaneRegistry reg;
  CellComplex cx(reg, unit_box());
  // Diagonal plane x = y passes through two vertical edges exactly.
  auto r = cx.split(0, reg.add({{1, -1, 0}, 0.0}));
  ASSERT_TRUE(r);
  EXPECT_NEAR(cx.cell_volume(r->neg) + cx.cell_volume(r->pos), 1.0, 1e-12);
  // Plane x + y + z = 1 through three vertices of the box.
  auto r2 = cx.split(r->pos, reg.add({{1, 1, 1}, -1.0}));
  ASSERT_TRUE(r2);
  expect_cells_closed(cx);
  expect_facets_shared(cx);
  EXPECT_NEAR(total_volume(cx), 1.0, 1e-12);
}

TEST(CellComplex, ManyRandomSplitsKeepTheComplexClosedAndConforming) {
  PlaneRegistry reg;
  CellComplex cx(reg, unit_box(10));
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), pos(1, 9);
  int splits = 0;
  for (int i = 0; i < 60; ++i) {
    Vec3 n{u(rng), u(rng), u(rng)};
    if (i % 3 == 0) n = {double(i % 2), double((i + 1) % 2), 0};  // axis planes: degenerate contacts
    const Vec3 at{pos(rng), pos(rng), pos(rng)};
    const uint32_t p = reg.add({n, -dot(normalized(n), at) * norm(n)});
    for (uint32_t c : cx.live_cells()) splits += cx.split(c, p).has_value();
  }
  EXPECT_GT(splits, 60);
  expect_cells_closed(cx);
  expect_facets_shared(cx);
  EXPECT_NEAR(total_volume(cx), 1000.0, 1e-8);
}

// After prepare_side_predicates() the side predicates only read the complex: evaluated on two
// threads at once they give what one thread gives (the level refinement relies on it,
// core/level_work.cpp). The planes pass through vertices and along edges, where the exact
// evaluation runs, and are added after the splits, so their exact planes are built lazily.
TEST(CellComplex, SidePredicatesOnSeveralThreadsAfterPreparation) {
  PlaneRegistry reg;
  CellComplex cx(reg, unit_box(10));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1), pos(1, 9);
  for (int i = 0; i < 25; ++i) {
    const Vec3 n{u(rng), u(rng), u(rng)};
    const uint32_t p = reg.add({n, -dot(normalized(n), Vec3{pos(rng), pos(rng), pos(rng)}) * norm(n)});
    for (uint32_t c : cx.live_cells()) cx.split(c, p);
  }
  std::vector<uint32_t> probes;  // planes through existing vertices (exact ties) and random ones
  const std::vector<uint32_t> cells = cx.live_cells();
  for (int i = 0; i < 40; ++i) {
    const Vec3 a = cx.point(cx.cell_vertices(cells[i % cells.size()])[0]);
    const Vec3 n = i % 2 ? Vec3{1, 0, 0} : Vec3{u(rng), u(rng), u(rng)};
    probes.push_back(reg.add({n, -dot(n, a)}));
  }
  cx.prepare_side_predicates();
  std::vector<int> serial, parallel(cells.size() * probes.size());
  for (uint32_t p : probes)
    for (uint32_t c : cells) serial.push_back(cx.cell_side(c, p));
  tbb::task_arena arena(2);
  arena.execute([&] {
    tbb::parallel_for(size_t(0), parallel.size(), size_t(1), [&](size_t k) {
      parallel[k] = cx.cell_side(cells[k % cells.size()], probes[k / cells.size()]);
    });
  });
  EXPECT_EQ(serial, parallel);
  EXPECT_NE(std::count(serial.begin(), serial.end(), 0), 0);  // some probes cut cells
  // From the cells' vertices listed once (the refinement's many candidates per cell), the same.
  std::vector<int> listed;
  for (uint32_t p : probes)
    for (uint32_t c : cells) listed.push_back(cx.vertices_side(cx.cell_vertices(c), p));
  EXPECT_EQ(serial, listed);
}

TEST(CellComplex, LeavesFollowTheBspTree) {
  PlaneRegistry reg;
  CellComplex cx(reg, unit_box());
  auto r = cx.split(0, reg.add({{0, 0, 1}, -0.25}));
  cx.split(r->pos, reg.add({{0, 1, 0}, -0.5}));
  std::vector<uint32_t> out;
  cx.leaves(0, out);
  EXPECT_EQ(out.size(), 3u);
  EXPECT_EQ(cx.cell_side(r->neg, reg.add({{0, 0, 1}, -0.25})), -1);
}

}  // namespace
}  // namespace mc
