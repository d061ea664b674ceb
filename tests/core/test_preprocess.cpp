// Preprocessing on synthetic buildings, clean and with injected defects (issue 3): the singleton
// cell must be closed, 2-manifold and within 2x the sampling interval of the clean building's.
#include "core/preprocess.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>

#include "buildings.hpp"
#include "core/decompose.hpp"
#include "core/hausdorff.hpp"
#include "core/soup.hpp"
#include "off_fixture.hpp"

namespace mc {
namespace {

constexpr double kCell = 0.5;

Preprocessed run(const PolygonMesh& m) {
  PreprocessParams p;
  p.cell_size = kCell;
  p.dist_thresh = kCell / 4;
  p.compute_hausdorff = true;
  return preprocess(m, p, Clock::now() + std::chrono::seconds(60));
}

double distance_between_cells(const Preprocessed& a, const Preprocessed& b) {
  return hausdorff(triangulate(singleton_mesh(a)), triangulate(singleton_mesh(b)), kCell / 4).symmetric;
}

using Defect = std::function<PolygonMesh(PolygonMesh)>;

PolygonMesh open_bottom(PolygonMesh m) {
  const int ground = m.label_index("GroundSurface");
  std::erase_if(m.faces, [&](const Polygon& f) { return f.semantic == ground; });
  return m;
}
PolygonMesh flip_30_percent(PolygonMesh m) {
  for (size_t i = 0; i < m.faces.size(); i += 3)
    for (auto& r : m.faces[i].rings) std::reverse(r.begin(), r.end());
  return m;
}
PolygonMesh duplicate_faces(PolygonMesh m) {
  const size_t n = m.faces.size();
  for (size_t i = 0; i < n; i += 2) m.faces.push_back(m.faces[i]);
  return m;
}
PolygonMesh missing_wall(PolygonMesh m) {
  const int wall = m.label_index("WallSurface");
  for (size_t i = 0; i < m.faces.size(); ++i)
    if (m.faces[i].semantic == wall) {
      m.faces.erase(m.faces.begin() + static_cast<long>(i));
      break;
    }
  return m;
}
PolygonMesh jitter_1mm(PolygonMesh m) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.001, 0.001);
  for (Vec3& v : m.vertices) v += Vec3{u(rng), u(rng), u(rng)};
  return m;
}
// A second copy of every wall, 1 cm outside and slightly larger, so that the copies cut through
// the neighbouring walls (self-intersecting duplicate walls).
PolygonMesh intersecting_duplicate_walls(PolygonMesh m) {
  const int wall = m.label_index("WallSurface");
  const size_t n = m.faces.size();
  for (size_t i = 0; i < n; ++i) {
    if (m.faces[i].semantic != wall) continue;
    const auto& ring = m.faces[i].rings[0];
    Vec3 c, nrm;
    for (size_t k = 0; k < ring.size(); ++k) {
      c += m.vertices[ring[k]];
      nrm += cross(m.vertices[ring[k]], m.vertices[ring[(k + 1) % ring.size()]]);
    }
    c = c / static_cast<double>(ring.size());
    nrm = normalized(nrm);
    Polygon copy{{{}}, wall};
    for (uint32_t v : ring) {
      m.vertices.push_back(c + (m.vertices[v] - c) * 1.05 + nrm * 0.01);
      copy.rings[0].push_back(static_cast<uint32_t>(m.vertices.size() - 1));
    }
    m.faces.push_back(copy);
  }
  return m;
}

struct Case {
  const char* name;
  PolygonMesh (*building)();
};

class Preprocess : public ::testing::TestWithParam<Case> {};

TEST_P(Preprocess, CleanBuildingGivesItsExactClosedCell) {
  const PolygonMesh m = GetParam().building();
  const Preprocessed pre = run(m);
  EXPECT_TRUE(pre.closed);
  EXPECT_TRUE(pre.manifold);
  ASSERT_EQ(pre.components.size(), 1u);
  EXPECT_LT(pre.hausdorff, 1e-6);  // every input plane is used: the cell is the building
}

TEST_P(Preprocess, DefectsKeepTheCellClosedAndClose) {
  const PolygonMesh clean = GetParam().building();
  const Preprocessed ref = run(clean);
  const std::pair<const char*, Defect> defects[] = {
      {"open bottom", open_bottom},          {"30% flipped faces", flip_30_percent},
      {"duplicated faces", duplicate_faces}, {"missing wall face", missing_wall},
      {"1 mm jitter", jitter_1mm},           {"intersecting duplicate walls", intersecting_duplicate_walls}};
  for (const auto& [name, defect] : defects) {
    SCOPED_TRACE(name);
    const Preprocessed pre = run(defect(clean));
    EXPECT_TRUE(pre.closed);
    EXPECT_TRUE(pre.manifold);
    EXPECT_LE(distance_between_cells(pre, ref), 2 * kCell);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Synthetic, Preprocess,
    ::testing::Values(Case{"box", test::box_building}, Case{"L", test::l_building},
                      Case{"U", test::u_building}, Case{"courtyard", test::courtyard_building},
                      Case{"stepped_tower", test::stepped_tower}, Case{"T", test::t_building},
                      Case{"cross_gable", test::cross_gable_house}, Case{"dormer", test::dormer_house}),
    [](const auto& info) { return std::string(info.param.name); });

// Real open-bottom inputs (walls and roof, no floor) at the paper's resolution: the cell's floor
// lies at the input's lowest level. A cell reaching out of the open bottom touches no input face;
// it must still get the full vote, not the few-point vote of cells the surface does not touch
// (sample8 once kept such a cell, hanging 8 m below the building down to the carving box).
TEST(Preprocess, OpenBottomCellStopsAtTheInputsLowestLevel) {
  int checked = 0;
  for (const auto& s : test::samples()) {
    if (s.name != "sample8" && s.name != "sample9" && s.name != "sample10") continue;
    const PreprocessParams p = test::paper_params(s);
    const PolygonMesh in = test::load_off(s.off.string());
    const Preprocessed pre = preprocess(in, p, Clock::now() + std::chrono::seconds(60));
    double in_lo = 1e300, cell_lo = 1e300;
    for (const Vec3& v : in.vertices) in_lo = std::min(in_lo, v.z);
    for (const Vec3& v : singleton_mesh(pre).vertices) cell_lo = std::min(cell_lo, v.z);
    EXPECT_GE(cell_lo, in_lo - p.dist_thresh) << s.name;
    EXPECT_TRUE(pre.closed) << s.name;
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

// sample18 (Hong Kong, float32 coordinates) is a stack of closed storey shells glued along their
// floor outlines. The oracle splits them into closed patches, one parity group each; welded at
// the other stages' tolerance, float-neighbour vertices made the split fail and plain parity
// lost the storeys at 95.5-102.7 m and 146-158 m (cell 102,675 m³; the paper's 112,680 m³).
TEST(Preprocess, StackedStoreyShellsOfAFloatInputAllStayInside) {
  int checked = 0;
  for (const auto& s : test::samples()) {
    if (s.name != "sample18") continue;
    const PreprocessParams p = test::paper_params(s);
    const Preprocessed pre =
        preprocess(test::load_off(s.off.string()), p, Clock::now() + std::chrono::seconds(60));
    double volume = 0;
    for (const auto& c : pre.components) volume += c.volume;
    EXPECT_NEAR(volume, 112680.0, 0.02 * 112680.0);
    EXPECT_TRUE(pre.closed);
    ++checked;
  }
  EXPECT_EQ(checked, 1);
}

// sample17 (Hong Kong) models its storeys' floors as sheets inside the solid, glued to the walls:
// parity alone loses the storeys under such sheets (180,742 m³ of the paper's 203,213 m³ at
// automatic resolution). With the enclosure fallback (preprocess.fill_enclosed) the cell has the
// paper's volume.
TEST(Preprocess, StoreysUnderInteriorFloorSheetsStayInside) {
  int checked = 0;
  for (const auto& s : test::samples()) {
    if (s.name != "sample17") continue;
    const PolygonMesh in = test::load_off(s.off.string());
    PreprocessParams p;
    p.compute_hausdorff = false;
    auto volume = [&](bool fill) {
      p.fill_enclosed = fill;
      const Preprocessed pre = preprocess(in, p, Clock::now() + std::chrono::seconds(60));
      EXPECT_TRUE(pre.closed && pre.manifold);
      double v = 0;
      for (const auto& c : pre.components) v += c.volume;
      return v;
    };
    const double paper = 203213.0;
    EXPECT_NEAR(volume(true), paper, 0.01 * paper);
    EXPECT_LT(volume(false), 0.93 * paper);
    ++checked;
  }
  EXPECT_EQ(checked, 1);
}

// A real closed 3D BAG building (tile 5910, NL.IMBAG.Pand.0503100000004560, LoD2.2, 56 faces;
// CC BY 4.0 3D BAG): at automatic resolution one carving cell, 36% of it outside, could only be
// cut by a plane passing 4.5 mm from one of its vertices (below the hair δ/10 = 4.7 mm). With
// min_gap that cut is made and the cell follows the building; without it a 7.6 m³ chunk of air
// stays inside.
TEST(Preprocess, HairBlockedCellIsCutWhenTheGapIsSafe) {
  const PolygonMesh m =
      test::load_off(std::string(MC_SOURCE_DIR) + "/tests/core/data/3dbag_0503100000004560.off");
  PreprocessParams p;
  p.compute_hausdorff = true;
  const Preprocessed with_gap = preprocess(m, p, Clock::now() + std::chrono::seconds(60));
  p.min_gap = 0;
  const Preprocessed without = preprocess(m, p, Clock::now() + std::chrono::seconds(60));
  EXPECT_TRUE(with_gap.closed && with_gap.manifold);
  EXPECT_LT(with_gap.hausdorff, 1.0);
  EXPECT_GT(without.hausdorff, 1.5);
}

// The fast path (docs/algorithm.md §6.6) is taken for a valid solid and refused, with the reason,
// for an input that is not one; a valid solid's cell is the same with and without it.
TEST(Preprocess, FastPathOnlyForValidSolidsAndSameCell) {
  PreprocessParams p;
  p.cell_size = kCell;
  p.dist_thresh = kCell / 4;
  p.compute_hausdorff = false;
  const auto deadline = Clock::now() + std::chrono::seconds(60);
  const PolygonMesh house = test::dormer_house();
  const Preprocessed fast = preprocess(house, p, deadline);
  EXPECT_TRUE(fast.fast_path);
  EXPECT_EQ(fast.fast_path_reason, "");
  PreprocessParams off = p;
  off.fast_path = false;
  const Preprocessed slow = preprocess(house, off, deadline);
  EXPECT_FALSE(slow.fast_path);
  EXPECT_EQ(slow.fast_path_reason, "fast path off");
  EXPECT_EQ(fast.cells, slow.cells);
  EXPECT_EQ(fast.inside_cells, slow.inside_cells);
  EXPECT_NEAR(fast.volume_check.cell, slow.volume_check.cell, 1e-9);
  EXPECT_LT(fast.oracle_points, slow.oracle_points + 1);  // same points, fewer rays each

  const Preprocessed flipped = preprocess(flip_30_percent(house), p, deadline);
  EXPECT_FALSE(flipped.fast_path);
  // Faces against their neighbours: a triangle that does not fit the shell, reversed (307) or not
  // even reversed (303), as val3dity builds it.
  EXPECT_TRUE(flipped.fast_path_reason.rfind("307 ", 0) == 0 ||
              flipped.fast_path_reason.rfind("303 ", 0) == 0)
      << flipped.fast_path_reason;
  const Preprocessed open = preprocess(missing_wall(house), p, deadline);
  EXPECT_FALSE(open.fast_path);
  EXPECT_FALSE(open.fast_path_reason.empty());
}

// A valid solid's cell that the surface only grazes (fitting noise of a face along one of its
// facets) is voted in a band along its facets (docs/algorithm.md §7.3): on two real 3D BAG
// buildings (CC BY 4.0) at automatic resolution the cell is the same as with the full vote, from
// at least 30% fewer points.
TEST(Preprocess, GrazedCellsVotedInABandGiveTheSameCell) {
  for (const char* name : {"3dbag_0503100000004560.off", "3dbag_0503100000018414.off"}) {
    SCOPED_TRACE(name);
    const PolygonMesh m = test::load_off(std::string(MC_SOURCE_DIR) + "/tests/core/data/" + name);
    PreprocessParams p;
    p.compute_hausdorff = false;
    p.region_votes = false;    // the cells the band leaves go point by point in both runs
    p.column_volumes = false;  // touched cells are voted, not measured
    const auto deadline = Clock::now() + std::chrono::seconds(60);
    const Preprocessed band = preprocess(m, p, deadline);
    p.grazed_cells = false;
    const Preprocessed full = preprocess(m, p, deadline);
    ASSERT_TRUE(band.fast_path) << band.fast_path_reason;
    EXPECT_EQ(band.cells, full.cells);
    EXPECT_EQ(band.inside_cells, full.inside_cells);
    EXPECT_EQ(band.volume_check.cell, full.volume_check.cell);
    EXPECT_EQ(singleton_mesh(band).vertices, singleton_mesh(full).vertices);
    EXPECT_LT(band.oracle_points, 0.7 * full.oracle_points);
  }
}

TEST(Preprocess, ColumnVolumesLabelValidSolidsWithoutSeedOrSamplePoints) {
  // Real 3D BAG buildings (valid solids): touched cells labelled by their exact inside volume
  // (docs/design.md "Inside volume by columns") give the same singleton cell whatever the seed,
  // within 0.5 % of the votes' cell, with fewer oracle queries (only untouched cells ask it).
  for (const char* name : {"3dbag_0503100000004560.off", "3dbag_0503100000018414.off"}) {
    SCOPED_TRACE(name);
    const PolygonMesh m = test::load_off(std::string(MC_SOURCE_DIR) + "/tests/core/data/" + name);
    PreprocessParams p;
    p.compute_hausdorff = false;
    const auto deadline = Clock::now() + std::chrono::seconds(60);
    const Preprocessed exact = preprocess(m, p, deadline);
    p.seed = 7;
    const Preprocessed reseeded = preprocess(m, p, deadline);
    p.column_volumes = false;
    const Preprocessed voted = preprocess(m, p, deadline);
    ASSERT_TRUE(exact.fast_path) << exact.fast_path_reason;
    EXPECT_EQ(exact.cells, reseeded.cells);
    EXPECT_EQ(exact.volume_check.cell, reseeded.volume_check.cell);
    EXPECT_EQ(singleton_mesh(exact).vertices, singleton_mesh(reseeded).vertices);
    EXPECT_NEAR(exact.volume_check.cell / voted.volume_check.cell, 1.0, 0.005);
    EXPECT_NEAR(exact.volume_check.ratio, 1.0, 0.005);
    EXPECT_LT(exact.oracle_points, voted.oracle_points);
  }
}

TEST(Preprocess, RegionVotesKeepTheSamplesCellsWithFewerQueries) {
  // Real inputs that are not valid solids (non-manifold edges, several shells, flipped faces), so
  // touched cells go to the parity vote: by regions or point by point, the same cell within
  // 0.5 % for a fraction of the oracle's queries (docs/design.md "Regions, not points").
  size_t tried = 0;
  for (const test::Sample& s : test::samples()) {
    if (s.name != "sample1" && s.name != "sample2" && s.name != "sample18") continue;
    SCOPED_TRACE(s.name);
    ++tried;
    const PolygonMesh m = test::load_off(s.off.string());
    PreprocessParams p = test::paper_params(s);
    const auto deadline = Clock::now() + std::chrono::seconds(120);
    const Preprocessed regions = preprocess(m, p, deadline);
    p.region_votes = false;
    const Preprocessed points = preprocess(m, p, deadline);
    ASSERT_FALSE(regions.fast_path);
    ASSERT_GT(points.volume_check.cell, 0);
    EXPECT_NEAR(regions.volume_check.cell / points.volume_check.cell, 1.0, 0.005);
    EXPECT_LT(regions.oracle_points, 0.7 * points.oracle_points);
  }
  if (tried == 0) GTEST_SKIP() << "the paper's samples are not beside the project (../shared)";
}

TEST(Preprocess, EmptyAndDegenerateInputsThrowClearErrors) {
  PreprocessParams p;
  const auto deadline = Clock::now() + std::chrono::seconds(10);
  EXPECT_THROW(preprocess(PolygonMesh{}, p, deadline), std::runtime_error);
  PolygonMesh flat;
  flat.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  flat.faces.push_back({{{0, 1, 2}}, -1});
  EXPECT_THROW(preprocess(flat, p, deadline), std::runtime_error);
}

}  // namespace
}  // namespace mc
