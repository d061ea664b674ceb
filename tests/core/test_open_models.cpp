// Open models (docs/algorithm.md §6.4, §6.5): the vertical roof-over-ground vote on
// synthetic open models against their closed references (datasets/open_models), the volume
// check, and a handful of 3D BAG buildings of the open variants (party walls removed, ground
// removed; tools/gen_open_variants.py --seed 19) against the closed original.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/params.hpp"
#include "core/open_input.hpp"
#include "core/preprocess.hpp"
#include "io/cityjson.hpp"
#include "io/cityjson_building.hpp"
#include "io/cityjson_reader.hpp"
#include "config/run_config.hpp"
#include "pipeline/job.hpp"
#include "report/report.hpp"

namespace mc::test {
namespace {

namespace fs = std::filesystem;

std::string source(const std::string& rel) { return std::string(MC_SOURCE_DIR) + "/" + rel; }

struct Cell {
  double volume = 0;
  VolumeCheck check;
  bool open = false;
  size_t hole_planes = 0, cells = 0;
  std::string info;
};

// The singleton cell of every Building of `path` (or of those in `only`), default parameters.
std::map<std::string, Cell> cells_of(const std::string& path, const std::set<std::string>& only = {},
                                     const PreprocessParams& p = {}) {
  io::CityJsonReader r(path);
  std::map<std::string, Cell> out;
  io::Feature f;
  while (r.next(f)) {
    if (!io::is_building(f) || (!only.empty() && !only.count(f.id))) continue;
    const io::BuildingInput b = io::extract_building(f, r.header());
    if (b.mesh.faces.empty()) continue;
    const Preprocessed pre = preprocess(b.mesh, p, Clock::time_point::max());
    Cell c;
    for (const auto& comp : pre.components) c.volume += comp.volume;
    c.check = pre.volume_check;
    c.open = pre.open_input;
    c.hole_planes = pre.hole_planes;
    c.cells = pre.cells;
    c.info = "holes " + std::to_string(pre.hole_planes) + " walls " +
             std::to_string(pre.boundary_wall_planes) + " cells " + std::to_string(pre.cells) + " boundary " +
             std::to_string(pre.open_boundary_length);
    for (const auto& pr : pre.problems) c.info += " | " + pr;
    out[f.id] = c;
  }
  return out;
}

// The open variants of `file` (tools/gen_open_variants.py --seed 19, `variants` e.g. "a,b,c") in a
// fresh directory under the build tree named after `tag`; empty when the generator fails.
fs::path open_variants(const std::string& file, const std::string& variants, const std::string& tag) {
  const fs::path dir = fs::path(MC_BINARY_DIR) / (tag + "_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string cmd = "python3 " + source("tools/gen_open_variants.py") + " " + file + " " +
                          dir.string() + " --seed 19 --variants " + variants + " --no-ajv > /dev/null";
  if (std::system(cmd.c_str()) != 0) {
    ADD_FAILURE() << cmd;
    return {};
  }
  return dir;
}

double only_volume(const std::map<std::string, Cell>& cells) {
  EXPECT_EQ(cells.size(), 1u);
  return cells.empty() ? 0 : cells.begin()->second.volume;
}

TEST(OpenModels, TerracedRowWithoutPartyWallsKeepsEveryHouse) {
  const auto open = cells_of(source("datasets/open_models/terraced_row.city.json"));
  const auto closed = cells_of(source("datasets/open_models/terraced_row.closed.city.json"));
  ASSERT_EQ(open.size(), 5u);
  for (const auto& [id, c] : open) {
    SCOPED_TRACE(id);
    EXPECT_NEAR(c.volume, 366.3, 0.01 * 366.3);
    EXPECT_NEAR(closed.at(id).volume, 366.3, 0.01 * 366.3);
    EXPECT_TRUE(c.open);
    EXPECT_EQ(c.check.oracle, "vertical");
    EXPECT_FALSE(c.check.flagged);
    // The closed reference: parity, checked against its own signed volume.
    EXPECT_FALSE(closed.at(id).open);
    EXPECT_EQ(closed.at(id).check.oracle, "parity");
    EXPECT_EQ(closed.at(id).check.method, "signed volume");
    EXPECT_NEAR(closed.at(id).check.ratio, 1.0, 0.01);
  }
}

// Roofs only: no wall and no ground says where the ground is, so the cell is what lies under the
// roofs down to the lowest input height (docs/algorithm.md §6.4): the gable prism, 10 x 7 x 3 / 2.
TEST(OpenModels, GableRoofOnlyIsTheRoofPrismOverTheLowestHeight) {
  const auto c = cells_of(source("datasets/open_models/gable_roof_only.city.json"));
  EXPECT_NEAR(only_volume(c), 105.0, 0.01 * 105.0);
  EXPECT_EQ(c.begin()->second.check.oracle, "vertical");
  EXPECT_FALSE(c.begin()->second.check.flagged);
  EXPECT_NEAR(only_volume(cells_of(source("datasets/open_models/gable_roof_only.closed.city.json"))), 455.0,
              4.55);
}

// With the terrain height a file gives (3D BAG h_maaiveld, Rotterdam TerrainHeight; here 0), a
// model of roofs only stands on the terrain: the whole house, as its closed reference.
TEST(OpenModels, RoofsOnlyStandOnTheTerrainHeightWhenTheFileGivesIt) {
  for (const auto& [name, reference] :
       {std::pair{"gable_roof_only", 455.0}, std::pair{"l_shape_roof_only", 498.0}}) {
    SCOPED_TRACE(name);
    io::CityJsonReader r(source(std::string("datasets/open_models/") + name + ".city.json"));
    io::Feature f;
    ASSERT_TRUE(r.next(f));
    const io::BuildingInput b = io::extract_building(f, r.header());
    const Preprocessed pre = preprocess(b.mesh, PreprocessParams{}, Clock::time_point::max(), 0.0);
    double v = 0;
    for (const auto& c : pre.components) v += c.volume;
    EXPECT_TRUE(pre.ground_from_terrain);
    EXPECT_NEAR(v, reference, 0.01 * reference);
    EXPECT_FALSE(pre.volume_check.flagged);
    // The pipeline reads it from the attributes.
    f.objects[f.id]["attributes"]["h_maaiveld"] = 0.0;
    Params p;
    p.dec.levels = {0.1};
    const pipeline::BuildingOutcome o = pipeline::run_building(f, r.header(), p, RunConfig{});
    EXPECT_EQ(o.status, "ok") << o.reason;
    EXPECT_NEAR(o.volume_check.cell, reference, 0.01 * reference);
  }
}

// The L: main block 10 x 6 m, eaves 6 m, ridge 9 m; the flat annex roof at 3 m is the lowest
// height: 10 x 6 x 3 + 10 x 6 x 3 / 2 = 270 m³ (the annex has no height above it).
TEST(OpenModels, LShapeRoofOnlyStandsOnItsLowestRoof) {
  const auto c = cells_of(source("datasets/open_models/l_shape_roof_only.city.json"));
  EXPECT_NEAR(only_volume(c), 270.0, 0.01 * 270.0);
  EXPECT_FALSE(c.begin()->second.check.flagged);
  EXPECT_NEAR(only_volume(cells_of(source("datasets/open_models/l_shape_roof_only.closed.city.json"))), 498.0,
              4.98);
}

// Storeys glued face to face with a floor sheet inside each: nothing of the tower is lost.
TEST(OpenModels, TowerOfInclinedPrismsWithFloorSheetsKeepsItsVolume) {
  const auto c = cells_of(source("datasets/open_models/tower_inclined_prisms.city.json"));
  EXPECT_NEAR(only_volume(c), 1036.8, 0.02 * 1036.8);
  EXPECT_FALSE(c.begin()->second.check.flagged);
}

// The volume check: forcing the parity oracle on the roof-only gable (whose parity cell is not
// the vertical estimate) runs the vertical vote as the second labelling and keeps it.
TEST(OpenModels, VolumeCheckRelabelsWithTheOtherOracle) {
  PreprocessParams p;
  p.oracle = "parity";
  const auto c = cells_of(source("datasets/open_models/gable_roof_only.city.json"), {}, p);
  ASSERT_EQ(c.size(), 1u);
  const VolumeCheck& v = c.begin()->second.check;
  EXPECT_EQ(v.method, "vertical columns");
  EXPECT_NEAR(v.estimate, 105.0, 1.0);
  EXPECT_NEAR(v.cell, 105.0, 0.01 * 105.0);
  EXPECT_FALSE(v.flagged);
  // Off: the first labelling stays, whatever the estimate.
  p.volume_check = 0;
  const auto off = cells_of(source("datasets/open_models/gable_roof_only.city.json"), {}, p);
  EXPECT_FALSE(off.begin()->second.check.relabelled);
  EXPECT_EQ(off.begin()->second.check.oracle, "parity");
}

// Closed inputs keep today's labelling: the parity oracle, no second labelling, the same cell as
// with the oracle forced to parity and the check off.
TEST(OpenModels, ClosedInputsKeepTheParityCell) {
  PreprocessParams old;
  old.oracle = "parity";
  old.volume_check = 0;
  for (const char* f : {"terraced_row.closed", "gable_roof_only.closed", "l_shape_roof_only.closed"}) {
    const std::string path = source(std::string("datasets/open_models/") + f + ".city.json");
    const auto now = cells_of(path), before = cells_of(path, {}, old);
    for (const auto& [id, c] : now) {
      SCOPED_TRACE(id);
      EXPECT_EQ(c.check.oracle, "parity");
      EXPECT_FALSE(c.check.relabelled);
      EXPECT_EQ(c.volume, before.at(id).volume);
    }
  }
}

// The pipeline carries a remaining disagreement to the Building (morphcut_volume_check) and to
// the run report; the status stays ok. A threshold of 1e-9 flags the column integration's own
// discretisation error on the roof-only gable.
TEST(OpenModels, AFlaggedDisagreementReachesTheBuildingAndTheReport) {
  io::CityJsonReader r(source("datasets/open_models/gable_roof_only.city.json"));
  io::Feature f;
  ASSERT_TRUE(r.next(f));
  Params p;
  p.pre.volume_check = 1e-9;
  p.dec.levels = {0.1};
  const pipeline::BuildingOutcome b = pipeline::run_building(f, r.header(), p, RunConfig{});
  EXPECT_EQ(b.status, "ok") << b.reason;
  EXPECT_TRUE(b.volume_check.flagged);
  EXPECT_EQ(b.volume_check.oracle, "vertical");
  EXPECT_EQ(b.volume_check.method, "vertical columns");
  const auto& o = b.feature.objects;
  bool found = false;
  for (const auto& obj : o)
    if (obj.is_object() && obj.contains("attributes") &&
        obj["attributes"].contains("morphcut_volume_check")) {
      const auto& v = obj["attributes"]["morphcut_volume_check"];
      EXPECT_NEAR(v["cell"].get<double>(), 105.0, 1.05);
      EXPECT_EQ(v["method"], "vertical columns");
      found = true;
    }
  EXPECT_TRUE(found);
  const auto j = report::building_report(b);
  ASSERT_TRUE(j.contains("volume_check"));
  EXPECT_TRUE(j["volume_check"]["flagged"].get<bool>());
  // With the default threshold the same building is not flagged.
  p.pre.volume_check = 0.05;
  EXPECT_FALSE(pipeline::run_building(f, r.header(), p, RunConfig{}).volume_check.flagged);
}

// Real data: 3D BAG buildings whose party walls (variant a), walls (b) or ground (c) are removed
// keep the closed original's cell volume within 2 %. The first six lost 13-44 % of it in variant
// (a) with the parity oracle alone (measured at 2ba24a3), and in (b) the parity oracle found no
// interior in 373 of the tile's 429 buildings; then come a detached house and a corner house.
// The last one (20703) was +3.7 % in (a): the missing south wall's plane passed 1.9 mm from the
// line where two jogs' planes meet and the hair rule kept it out (line snapping, §4).
// MC_OPEN_DEBUG=1 prints every cell, estimate and oracle.
TEST(OpenModels, ThreeDBagVariantsKeepTheOriginalVolume) {
  const std::string tile =
      source("../shared/datasets/cityjson/upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20.city.json");
  if (!fs::exists(tile)) GTEST_SKIP() << "shared data not found: " << tile;
  const fs::path dir = open_variants(tile, "a,b,c", "open_models");
  ASSERT_FALSE(dir.empty());
  const std::set<std::string> ids = {
      "NL.IMBAG.Pand.0503100000020594", "NL.IMBAG.Pand.0503100000020515", "NL.IMBAG.Pand.0503100000020426",
      "NL.IMBAG.Pand.0503100000020424", "NL.IMBAG.Pand.0503100000021001", "NL.IMBAG.Pand.0503100000018414",
      "NL.IMBAG.Pand.0503100000004247", "NL.IMBAG.Pand.0503100000029912", "NL.IMBAG.Pand.0503100000020703"};
  const auto ref = cells_of(tile, ids);
  ASSERT_EQ(ref.size(), ids.size());
  for (const auto& [id, c] : ref) {  // closed originals: parity, checked against their own volume
    EXPECT_FALSE(c.open) << id;
    EXPECT_EQ(c.check.oracle, "parity") << id;
    EXPECT_EQ(c.check.method, "signed volume") << id;
  }
  for (const std::string v : {"a", "b", "c"}) {
    const auto var = cells_of((dir / ("3dbag_v210908_fd2cee53_5910.v20." + v + ".city.json")).string(), ids);
    ASSERT_EQ(var.size(), ids.size()) << v;
    for (const auto& [id, c] : var) {
      SCOPED_TRACE(v + " " + id);
      if (std::getenv("MC_OPEN_DEBUG"))
        std::printf("%s %s ref %.2f cell %.2f est %.2f (%s) oracle %s open %d relabel %d\n", v.c_str(),
                    id.c_str(), ref.at(id).volume, c.volume, c.check.estimate, c.check.method.c_str(),
                    c.check.oracle.c_str(), int(c.open), int(c.check.relabelled));
      if (std::getenv("MC_OPEN_DEBUG"))
        std::printf("   %s\n   ref %s\n", c.info.c_str(), ref.at(id).info.c_str());
      EXPECT_NEAR(c.volume / ref.at(id).volume, 1.0, 0.02);
      EXPECT_FALSE(c.check.flagged);
    }
  }
  fs::remove_all(dir);
}

// Real data: 3D BAG buildings whose walls stop 0.3 m above their ground (variant e). The loop along
// the walls' lower edges once gave a horizontal hole plane that cut every cell at 0.3 m: more cells
// than the closed original (72, 48 and 84 cells against 53, 38 and 67), and a different part at level
// 0.01 for 004247 (5 parts instead of 4, docs/algorithm.md §6.4). Now the gap is closed by the open
// boundary's vertical planes only, and the carving makes about as many cells as for the original.
TEST(OpenModels, GapUnderTheWallsIsNotAHorizontalFace) {
  const std::string tile =
      source("../shared/datasets/cityjson/upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20.city.json");
  if (!fs::exists(tile)) GTEST_SKIP() << "shared data not found: " << tile;
  const fs::path dir = open_variants(tile, "e", "open_models_e");
  ASSERT_FALSE(dir.empty());
  const std::set<std::string> ids = {"NL.IMBAG.Pand.0503100000004247", "NL.IMBAG.Pand.0503100000025484",
                                     "NL.IMBAG.Pand.0503100000020433"};
  const auto ref = cells_of(tile, ids);
  const auto var = cells_of((dir / "3dbag_v210908_fd2cee53_5910.v20.e.city.json").string(), ids);
  ASSERT_EQ(var.size(), ids.size());
  for (const auto& [id, c] : var) {
    SCOPED_TRACE(id + ": " + c.info);
    EXPECT_TRUE(c.open);
    EXPECT_EQ(c.hole_planes, 0u);
    EXPECT_LE(c.cells, ref.at(id).cells + 2);
    EXPECT_NEAR(c.volume / ref.at(id).volume, 1.0, 0.005);
  }
  fs::remove_all(dir);
}

// Real data: a Rotterdam house with its ground removed (variant c). At the roof's corner the
// missing gable wall's plane passed 0.2 mm from the line where the two side walls' fitted planes
// meet; the hair rule kept it out of every cell there and a 14 m³ wedge beyond the gable stayed
// inside (+4.3 %). Anchored on that line, the wall is carved (line snapping, docs/algorithm.md §4).
TEST(OpenModels, MissingWallPlaneIsSnappedToTheLineItPassesAHairFrom) {
  const std::string file = source("../shared/datasets/cityjson/cjio/rotterdam/rotterdam_subset.json");
  if (!fs::exists(file)) GTEST_SKIP() << "shared data not found: " << file;
  const fs::path dir = open_variants(file, "c", "line_snap");
  ASSERT_FALSE(dir.empty());
  const std::string id = "{23D8CA22-0C82-4453-A11E-B3F2B3116DB4}";
  const double ref = only_volume(cells_of(file, {id}));
  const auto var = cells_of((dir / "rotterdam_subset.c.city.json").string(), {id});
  ASSERT_EQ(var.size(), 1u);
  EXPECT_TRUE(var.begin()->second.open);
  EXPECT_NEAR(var.begin()->second.volume / ref, 1.0, 0.005) << var.begin()->second.info;
  fs::remove_all(dir);
}

// Real data: the tile's largest open case, 0503100000032914 (1,784 faces) with 30 % of its walls
// removed (variant d). Its vertical labelling's carving holds the building, but the pinch repair
// then flipped a whole 7,263 m³ cell out of it (a block of the east wing: 5.0 % under the closed
// original, saved only when the volume check's parity labelling happened to come closer). The
// repair now cuts such a cell down and flips a piece along the pinch (algorithm.md §8), so the
// vertical labelling alone stays within 2 %, and the kept cell is not flagged.
TEST(OpenModels, AnOpenCellKeepsTheBlockAPinchRepairUsedToFlip) {
  const std::string tile =
      source("../shared/datasets/cityjson/upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20.city.json");
  if (!fs::exists(tile)) GTEST_SKIP() << "shared data not found: " << tile;
  const fs::path dir = open_variants(tile, "d", "open_models_d");
  ASSERT_FALSE(dir.empty());
  const std::string id = "NL.IMBAG.Pand.0503100000032914";
  const std::string variant = (dir / "3dbag_v210908_fd2cee53_5910.v20.d.city.json").string();
  const double ref = only_volume(cells_of(tile, {id}));
  PreprocessParams vertical_only;
  vertical_only.oracle = "vertical";
  vertical_only.volume_check = 0;  // the first labelling, as it comes out of the carving and repairs
  const auto first = cells_of(variant, {id}, vertical_only);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_TRUE(first.begin()->second.open);
  EXPECT_NEAR(first.begin()->second.volume / ref, 1.0, 0.02) << first.begin()->second.info;
  const auto kept = cells_of(variant, {id});
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_NEAR(kept.begin()->second.volume / ref, 1.0, 0.02) << kept.begin()->second.info;
  EXPECT_FALSE(kept.begin()->second.check.flagged);
  fs::remove_all(dir);
}

// Real data: a DH building of three parts on a slope whose walls start at 5.76, 6.06 and 6.16 m,
// with its ground surfaces removed (variant c). Without floors the vertical vote stood every
// column on the lowest height, and the two higher parts gained the air beneath them (+2.2 % of
// the closed original's volume); the open bottoms above the lowest level are now its floors.
TEST(OpenModels, PartsOnHigherGroundWithoutAGroundStandOnTheirWalls) {
  const std::string file = source("../shared/datasets/cityjson/upgraded-2.0/DH_01_subs.v20.city.json");
  if (!fs::exists(file)) GTEST_SKIP() << "shared data not found: " << file;
  const fs::path dir = open_variants(file, "c", "open_bottoms");
  ASSERT_FALSE(dir.empty());
  const std::string id = "GUID_13974D93-CB4F-4B5A-AB1E-577DD9928CF2";
  const double ref = only_volume(cells_of(file, {id}));
  io::CityJsonReader r((dir / "DH_01_subs.v20.c.city.json").string());
  io::Feature f;
  bool found = false;
  while (r.next(f)) {
    if (f.id != id) continue;
    found = true;
    const Preprocessed pre =
        preprocess(io::extract_building(f, r.header()).mesh, {}, Clock::time_point::max());
    double volume = 0;
    for (const auto& comp : pre.components) volume += comp.volume;
    EXPECT_TRUE(pre.open_input);
    EXPECT_GT(pre.open_bottom_triangles, 0u);
    EXPECT_NEAR(volume / ref, 1.0, 0.01);
    EXPECT_NEAR(pre.volume_check.estimate / ref, 1.0, 0.01);
  }
  EXPECT_TRUE(found);
  fs::remove_all(dir);
}

// The floors of the vertical vote: a horizontal hole with a roof above its inside and nothing
// below is an open bottom; with a ground below (the gap under walls that stop short of it) or
// with nothing above (a missing flat roof) it is not.
TEST(OpenModels, OpenBottomsAreHolesWithARoofAboveAndNothingBelow) {
  auto square = [](double z) { return std::vector<Vec3>{{0, 0, z}, {10, 0, z}, {10, 10, z}, {0, 10, z}}; };
  auto soup_of = [&](const std::vector<double>& heights) {
    TriangleSoup s;
    for (double z : heights) {
      const uint32_t b = static_cast<uint32_t>(s.vertices.size());
      for (const Vec3& v : square(z)) s.vertices.push_back(v);
      s.triangles.push_back({b, b + 1, b + 2});
      s.triangles.push_back({b, b + 2, b + 3});
    }
    s.source_face.assign(s.triangles.size(), 0);
    return s;
  };
  auto hole_at = [&](double z) {
    HolePlane h;
    h.plane = {{0, 0, 1}, -z};
    for (const Vec3& v : square(z)) h.bbox.add(v), h.loop.push_back(v);
    h.area = 100;
    return h;
  };
  const double angle = 10 * M_PI / 180;
  {  // roof at 5, walls from 0.3, no ground: the floor at 0.3
    const TriangleSoup roof = soup_of({5});
    const VerticalOracle v(roof, std::vector<uint8_t>(roof.triangles.size(), 1), 0.01, 0.3);
    const TriangleSoup floors = open_bottoms({hole_at(0.3)}, v, v, 0.01, angle);
    EXPECT_EQ(floors.triangles.size(), 2u);
    for (const Vec3& p : floors.vertices) EXPECT_DOUBLE_EQ(p.z, 0.3);
  }
  {  // the same with a ground at 0: the gap under the walls, no floor
    const TriangleSoup both = soup_of({0, 5});
    const VerticalOracle v(both, std::vector<uint8_t>(both.triangles.size(), 1), 0.01, 0);
    EXPECT_TRUE(open_bottoms({hole_at(0.3)}, v, v, 0.01, angle).triangles.empty());
  }
  {  // a missing flat roof at 5 over a ground: no floor
    const TriangleSoup ground = soup_of({0});
    const VerticalOracle v(ground, std::vector<uint8_t>(ground.triangles.size(), 1), 0.01, 0);
    EXPECT_TRUE(open_bottoms({hole_at(5)}, v, v, 0.01, angle).triangles.empty());
  }
}

}  // namespace
}  // namespace mc::test

namespace mc::test {
namespace {

// The open boundary's coverage test by brute force, every edge against every other (the form the
// candidate filter of analyse_open_input replaced): the same uncovered length and edges on every
// Building of the open variants and of the 3D BAG tile, open or not.
TEST(OpenModels, BoundaryCoverageEqualsTheBruteForceTest) {
  auto brute = [](const PolygonMesh& mesh, double dist, double& uncovered_length, size_t& uncovered_edges) {
    double lowest = 1e300;
    for (const Vec3& v : mesh.vertices) lowest = std::min(lowest, v.z);
    std::map<std::pair<uint32_t, uint32_t>, int> uses;
    for (const Polygon& f : mesh.faces)
      for (const auto& r : f.rings)
        for (size_t i = 0; i < r.size(); ++i) {
          const uint32_t a = r[i], b = r[(i + 1) % r.size()];
          if (a != b) ++uses[{std::min(a, b), std::max(a, b)}];
        }
    std::vector<std::pair<Vec3, Vec3>> edges;
    for (const auto& [e, n] : uses)
      if (n == 1) edges.emplace_back(mesh.vertices[e.first], mesh.vertices[e.second]);
    auto seg = [](const Vec3& p, const Vec3& a, const Vec3& b) {
      const Vec3 ab = b - a;
      const double l2 = dot(ab, ab);
      const double t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
      return norm(p - (a + ab * t));
    };
    uncovered_length = 0;
    uncovered_edges = 0;
    for (size_t i = 0; i < edges.size(); ++i) {
      const auto& [a, b] = edges[i];
      const double len = norm(b - a);
      if (len <= 0) continue;
      const Vec3 d = (b - a) * (1.0 / len);
      int uncovered = 0;
      for (int s = 0; s < 4; ++s) {
        const Vec3 p = a + (b - a) * ((2 * s + 1) / 8.0);
        bool covered = false;
        for (size_t j = 0; j < edges.size() && !covered; ++j) {
          if (j == i) continue;
          const Vec3 e = edges[j].second - edges[j].first;
          const double el = norm(e);
          if (el <= 0 || std::abs(dot(e, d)) < 0.99 * el) continue;
          covered = seg(p, edges[j].first, edges[j].second) <= dist;
        }
        uncovered += !covered;
      }
      if (uncovered) {
        if (std::max(a.z, b.z) > lowest + dist) uncovered_length += len * uncovered / 4.0;
        ++uncovered_edges;
      }
    }
  };
  size_t buildings = 0, open = 0;
  for (const char* rel :
       {"datasets/open_models/terraced_row.city.json", "datasets/open_models/gable_roof_only.city.json",
        "datasets/open_models/l_shape_roof_only.city.json",
        "datasets/open_models/tower_inclined_prisms.city.json", "datasets/3dbag/3dbag_5910.city.json"}) {
    io::CityJsonReader r(source(rel));
    io::Feature f;
    while (r.next(f)) {
      if (!io::is_building(f)) continue;
      const io::BuildingInput b = io::extract_building(f, r.header());
      if (b.mesh.faces.empty()) continue;
      for (double dist : {0.05, 0.5}) {
        const OpenInput o = analyse_open_input(b.mesh, dist);
        double length = 0;
        size_t count = 0;
        brute(b.mesh, dist, length, count);
        EXPECT_EQ(o.uncovered_length, length) << rel << " " << f.id << " δ " << dist;
        EXPECT_EQ(o.uncovered_edges.size(), count) << rel << " " << f.id << " δ " << dist;
        open += count > 0;
      }
      ++buildings;
    }
  }
  EXPECT_GT(buildings, 400u);
  EXPECT_GT(open, 10u);  // the comparison saw uncovered boundaries, not only closed shells
}

}  // namespace
}  // namespace mc::test
