// run_building on real 3D BAG buildings: parts, attributes, closed solids, failure and skip paths.
#include <cmath>

#include "io/cityjson.hpp"
#include "pipeline/job.hpp"
#include "pipeline_fixtures.hpp"

namespace mc::pipeline {
using namespace mc::massing;
using namespace mc::output;
using namespace mc::report;
namespace {

using mc::test::json;

std::vector<mc::io::Feature> read_all(const std::string& path, mc::io::Header& h) {
  mc::io::CityJsonReader r(path);
  h = r.header();
  std::vector<mc::io::Feature> out;
  mc::io::Feature f;
  while (r.next(f)) out.push_back(std::move(f));
  return out;
}

// The feature's objects and vertices as one CityJSON-like document for solid_defect.
json vertices_json(const mc::io::Feature& f) {
  json v = json::array();
  for (const auto& p : f.vertices) v.push_back({p.x, p.y, p.z});
  return v;
}

TEST(Job, DecomposesA3dBagBuildingIntoClosedParts) {
  MC_REQUIRE_DATA(path, "cjseq/3dbag_b2.city.json");
  mc::io::Header h;
  auto features = read_all(path, h);
  ASSERT_EQ(features.size(), 2u);
  const Params p = mc::test::default_config().params;
  const RunConfig rc;
  const mc::io::Feature input = features[0];
  const BuildingOutcome b = run_building(input, h, p, rc);
  ASSERT_TRUE(b.is_building);
  EXPECT_EQ(b.status, "ok") << b.reason;
  EXPECT_EQ(b.lod, "2.2");
  ASSERT_EQ(b.levels.size(), p.dec.levels.size());

  const json& objs = b.feature.objects;
  const json& building = objs.at(b.id);
  EXPECT_EQ(building["attributes"]["morphcut_status"], "ok");
  EXPECT_FALSE(building["attributes"].contains("morphcut_reason"));
  EXPECT_TRUE(building["attributes"]["morphcut_hausdorff"].is_number());
  // Input objects kept as they were (the original BuildingPart with its geometry).
  for (auto it = input.objects.begin(); it != input.objects.end(); ++it) {
    ASSERT_TRUE(objs.contains(it.key()));
    if (it.key() != b.id) { EXPECT_EQ(objs[it.key()], it.value()); }
  }
  // Input vertices untouched, new ones appended.
  ASSERT_GT(b.feature.vertices.size(), input.vertices.size());
  for (size_t i = 0; i < input.vertices.size(); ++i) EXPECT_EQ(b.feature.vertices[i], input.vertices[i]);

  const json verts = vertices_json(b.feature);
  size_t total_parts = 0;
  for (const LevelOutcome& l : b.levels) {
    EXPECT_GE(l.parts, 1u);
    EXPECT_EQ(l.threshold, p.dec.levels[l.index]);
    for (size_t j = 0; j < l.parts; ++j) {
      const std::string id = b.id + "-mc" + std::to_string(l.index) + "-" + std::to_string(j);
      ASSERT_TRUE(objs.contains(id)) << id;
      const json& part = objs[id];
      EXPECT_EQ(part["type"], "BuildingPart");
      EXPECT_EQ(part["parents"], json::array({b.id}));
      EXPECT_NE(std::find(building["children"].begin(), building["children"].end(), id),
                building["children"].end());
      EXPECT_EQ(part["attributes"]["morphcut_level"], l.threshold);
      EXPECT_EQ(part["attributes"]["morphcut_index"], j);
      EXPECT_GT(part["attributes"]["volume"].get<double>(), 0);
      const double c = part["attributes"]["convexity"].get<double>();
      EXPECT_GT(c, 0.5);
      EXPECT_LE(c, 1.0);
      const std::string level_prefix = b.id + "-mc" + std::to_string(l.index) + "-";
      for (const auto& n : part["attributes"]["neighbours"]) {
        EXPECT_TRUE(objs.contains(n.get<std::string>()));
        EXPECT_TRUE(n.get<std::string>().starts_with(level_prefix)) << n;  // a part of the same level
      }
      ASSERT_EQ(part["geometry"].size(), 1u);
      const json& g = part["geometry"][0];
      EXPECT_EQ(g["lod"], "2.2");
      EXPECT_EQ(mc::test::solid_defect(g, verts), "") << id;
      // Semantics: one value per surface, cut faces present as ClosureSurface (a decomposed
      // concave building has cuts).
      ASSERT_TRUE(g.contains("semantics"));
      EXPECT_EQ(g["semantics"]["values"][0].size(), g["boundaries"][0].size());
      ++total_parts;
    }
  }
  EXPECT_EQ(b.size.parts_written, total_parts);
  // The finest level of a concave building has more than one part, with ClosureSurface cuts.
  const LevelOutcome& fine = b.levels.back();
  ASSERT_GT(fine.parts, 1u);
  bool closure = false;
  for (const auto& s :
       objs[b.id + "-mc" + std::to_string(fine.index) + "-0"]["geometry"][0]["semantics"]["surfaces"])
    closure = closure || s["type"] == "ClosureSurface";
  EXPECT_TRUE(closure);
  // Volumes of one level add up to the building volume.
  double sum = 0;
  for (size_t j = 0; j < fine.parts; ++j)
    sum += objs[b.id + "-mc" + std::to_string(fine.index) + "-" + std::to_string(j)]["attributes"]["volume"]
               .get<double>();
  ASSERT_TRUE(b.measures.volume.has_value());
  EXPECT_NEAR(sum, *b.measures.volume, 1e-6 * *b.measures.volume);
  EXPECT_EQ(b.measures.centroid_method, "solid");
  EXPECT_EQ(b.measures.footprint_method, "ground");
  EXPECT_GT(*b.measures.footprint_area, 10.0);
  EXPECT_GT(*b.measures.height, 2.0);
}

// A level with the same parts as the level before it is that level's encoding under its own ids
// (job.cpp, `relabelled`): the same geometry, its own level, index and neighbour ids.
TEST(Job, ALevelWithTheSamePartsAsTheLastIsWrittenUnderItsOwnIds) {
  MC_REQUIRE_DATA(path, "cjseq/3dbag_b2.city.json");
  mc::io::Header h;
  auto features = read_all(path, h);
  const Params p = mc::test::default_config().params;
  size_t repeated = 0;
  for (const auto& input : features) {
    const BuildingOutcome b = run_building(input, h, p, RunConfig{});
    ASSERT_EQ(b.status, "ok") << b.reason;
    const json& objs = b.feature.objects;
    auto id = [&](size_t level, size_t j) {
      return b.id + "-mc" + std::to_string(level) + "-" + std::to_string(j);
    };
    for (size_t k = 1; k < b.levels.size(); ++k) {
      const LevelOutcome &prev = b.levels[k - 1], &l = b.levels[k];
      if (l.parts != prev.parts || l.cost != prev.cost) continue;
      ++repeated;
      for (size_t j = 0; j < l.parts; ++j) {
        const json& a = objs.at(id(prev.index, j));
        const json& c = objs.at(id(l.index, j));
        EXPECT_EQ(c["geometry"], a["geometry"]);
        EXPECT_EQ(c["attributes"]["morphcut_level"], l.threshold);
        EXPECT_EQ(c["attributes"]["morphcut_index"], j);
        ASSERT_EQ(c["attributes"]["neighbours"].size(), a["attributes"]["neighbours"].size());
        for (size_t n = 0; n < a["attributes"]["neighbours"].size(); ++n) {
          std::string expected = a["attributes"]["neighbours"][n].get<std::string>();
          const std::string from = "-mc" + std::to_string(prev.index) + "-";
          expected.replace(expected.rfind(from), from.size(), "-mc" + std::to_string(l.index) + "-");
          EXPECT_EQ(c["attributes"]["neighbours"][n], expected);
        }
      }
    }
  }
  EXPECT_GT(repeated, 0u);  // the two houses keep their parts over some levels
}

TEST(Job, RunningOnItsOwnOutputGivesTheSameParts) {
  MC_REQUIRE_DATA(path, "cjseq/3dbag_b2.city.json");
  mc::io::Header h;
  auto features = read_all(path, h);
  Params p = mc::test::default_config().params;
  p.dec.levels = {0.1};  // one level keeps this quick
  const RunConfig rc;
  const BuildingOutcome once = run_building(features[1], h, p, rc);
  ASSERT_EQ(once.status, "ok") << once.reason;
  const BuildingOutcome twice = run_building(once.feature, h, p, rc);
  ASSERT_EQ(twice.status, "ok") << twice.reason;
  EXPECT_EQ(twice.feature.objects, once.feature.objects);
}

TEST(Job, BrokenGeometryFailsAndPassesThroughUnchanged) {
  MC_REQUIRE_DATA(path, "cjseq/3dbag_b2.city.json");
  mc::io::Header h;
  auto features = read_all(path, h);
  mc::io::Feature bad = features[0];
  for (auto& v : bad.vertices) v.z = 0;  // flattened: no volume, nothing can be inside
  const BuildingOutcome b =
      run_building(bad, h, mc::test::default_config().params, mc::test::default_config().run);
  EXPECT_EQ(b.status, "failed");
  EXPECT_FALSE(b.reason.empty());
  EXPECT_EQ(b.feature.vertices.size(), bad.vertices.size());
  json expected = bad.objects;
  expected[b.id]["attributes"]["morphcut_status"] = "failed";
  expected[b.id]["attributes"]["morphcut_reason"] = b.reason;
  EXPECT_EQ(b.feature.objects, expected);
  EXPECT_TRUE(b.levels.empty());
}

TEST(Job, MissingLodIsSkippedWithTheAvailableLods) {
  MC_REQUIRE_DATA(path, "cjseq/3dbag_b2.city.json");
  mc::io::Header h;
  auto features = read_all(path, h);
  RunConfig rc;
  rc.lod = "1.3";
  const BuildingOutcome b = run_building(features[0], h, mc::test::default_config().params, rc);
  EXPECT_EQ(b.status, "skipped");
  EXPECT_NE(b.reason.find("1.3"), std::string::npos) << b.reason;
  EXPECT_NE(b.reason.find("2.2"), std::string::npos) << b.reason;
  EXPECT_EQ(b.feature.objects[b.id]["attributes"]["morphcut_status"], "skipped");
  EXPECT_EQ(b.feature.vertices.size(), features[0].vertices.size());
}

TEST(Job, NonBuildingsPassThroughUntouched) {
  MC_REQUIRE_DATA(path, "cjio/dummy/dummy.json");
  mc::io::Header h;
  auto features = read_all(path, h);
  bool seen = false;
  for (const auto& f : features) {
    if (mc::io::is_building(f)) continue;
    seen = true;
    const BuildingOutcome b =
        run_building(f, h, mc::test::default_config().params, mc::test::default_config().run);
    EXPECT_FALSE(b.is_building);
    EXPECT_EQ(b.feature.objects, f.objects);
    EXPECT_EQ(b.feature.vertices.size(), f.vertices.size());
  }
  EXPECT_TRUE(seen);
}

TEST(Job, ZeroTimeoutIsNoDeadlineButATinyOneGivesPartialWithAReason) {
  MC_REQUIRE_DATA(path, "cjseq/3dbag_b2.city.json");
  mc::io::Header h;
  auto features = read_all(path, h);
  Params p = mc::test::default_config().params;
  p.timeout_s = 1e-6;  // expires at once: the job must still return a complete, written result
  const BuildingOutcome b = run_building(features[0], h, p, mc::test::default_config().run);
  ASSERT_TRUE(b.status == "partial" || b.status == "failed") << b.status;
  EXPECT_FALSE(b.reason.empty());
  if (b.status == "partial") {
    ASSERT_EQ(b.levels.size(), p.dec.levels.size());
    const json verts = vertices_json(b.feature);
    for (const auto& l : b.levels)
      for (size_t j = 0; j < l.parts; ++j) {
        const std::string id = b.id + "-mc" + std::to_string(l.index) + "-" + std::to_string(j);
        ASSERT_TRUE(b.feature.objects.contains(id));
        EXPECT_EQ(mc::test::solid_defect(b.feature.objects[id]["geometry"][0], verts), "") << id;
      }
  }
}

}  // namespace
}  // namespace mc::pipeline
