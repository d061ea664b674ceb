// Massing analytics (docs/massing.md) on synthetic buildings with known answers, through the real
// pipeline (run_building: preprocess, decompose, encode, analytics) at the default config.
#include <gtest/gtest.h>

#include <map>

#include "config/config.hpp"
#include "pipeline/job.hpp"
#include "massing/massing.hpp"
#include "tests/core/synthetic_buildings.hpp"

namespace mc::pipeline {
using namespace mc::massing;
using namespace mc::report;
namespace {

using mc::test::box;
using mc::test::gable_house;
using mc::test::prism;
using nlohmann::json;

// Several closed shells as one building (the oracle takes their union, docs/algorithm.md §6.2).
PolygonMesh join(const std::vector<PolygonMesh>& shells) {
  PolygonMesh out;
  for (const PolygonMesh& s : shells) {
    const uint32_t base = static_cast<uint32_t>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), s.vertices.begin(), s.vertices.end());
    for (Polygon f : s.faces) {
      for (auto& r : f.rings)
        for (auto& v : r) v += base;
      f.semantic = f.semantic >= 0 ? out.label_index(s.semantic_labels[static_cast<size_t>(f.semantic)]) : -1;
      out.faces.push_back(std::move(f));
    }
  }
  return out;
}

mc::io::Header header() {
  mc::io::Header h;
  h.version = "2.0";
  h.root = {{"type", "CityJSON"},
            {"version", "2.0"},
            {"transform", {{"scale", {0.001, 0.001, 0.001}}, {"translate", {0, 0, 0}}}}};
  return h;
}

// A Building with one LoD 2.2 MultiSurface, moved to RD-like coordinates.
mc::io::Feature feature(const PolygonMesh& m) {
  mc::io::Feature f;
  f.id = "B";
  for (const Vec3& v : m.vertices) f.vertices.push_back({v.x + 85000, v.y + 446000, v.z});
  json boundaries = json::array(), values = json::array(), surfaces = json::array();
  std::map<int, int> label;
  for (const Polygon& p : m.faces) {
    json surface = json::array();
    for (const auto& r : p.rings) surface.push_back(r);
    boundaries.push_back(surface);
    const std::string name =
        p.semantic >= 0 ? m.semantic_labels[static_cast<size_t>(p.semantic)] : "WallSurface";
    int k = -1;
    for (size_t i = 0; i < surfaces.size(); ++i)
      if (surfaces[i]["type"] == name) k = static_cast<int>(i);
    if (k < 0) {
      surfaces.push_back({{"type", name}});
      k = static_cast<int>(surfaces.size() - 1);
    }
    values.push_back(k);
  }
  f.objects[f.id] = {
      {"type", "Building"},
      {"attributes", json::object()},
      {"geometry", json::array({{{"type", "MultiSurface"},
                                 {"lod", "2.2"},
                                 {"boundaries", boundaries},
                                 {"semantics", {{"surfaces", surfaces}, {"values", values}}}}})}};
  return f;
}

struct Result {
  BuildingOutcome b;
  std::map<std::string, int> roles;  // at the analysis level
  const LevelMassing* level = nullptr;
};

Result run(const PolygonMesh& m) {
  const LoadedConfig cfg = load_config_string("");
  Result r;
  r.b = run_building(feature(m), header(), cfg.params, RunConfig{});
  for (const auto& L : r.b.massing.levels)
    if (L.threshold == r.b.massing.features.level) r.level = &L;
  if (r.level)
    for (const auto& p : r.level->parts) ++r.roles[p.role];
  return r;
}

std::string describe(const Result& r) {
  std::string s = r.b.status + " " + r.b.reason + ";";
  if (r.level)
    for (const auto& p : r.level->parts) {
      s += " [" + p.role + " z " + std::to_string(p.z_min) + ".." + std::to_string(p.z_max) + " V " +
           std::to_string(p.volume) + " A " + std::to_string(p.footprint_area) + (p.grounded ? " g" : "") +
           " c:";
      for (const auto& c : p.contacts) s += " " + std::to_string(c.other) + c.kind + std::to_string(c.above);
      s += "]";
    }
  return s;
}

using Roles = std::map<std::string, int>;

TEST(Massing, BoxIsOneMainPart) {
  const Result r = run(box({0, 0, 0}, {12, 10, 8}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  ASSERT_TRUE(r.level);
  EXPECT_EQ(r.roles, (Roles{{"main", 1}})) << describe(r);
  const PartMassing& p = r.level->parts[0];
  EXPECT_NEAR(p.z_min, 0, 1e-6);
  EXPECT_NEAR(p.z_max, 8, 1e-6);
  EXPECT_NEAR(p.footprint_area, 120, 1e-6);
  EXPECT_NEAR(p.hull_volume, 960, 1e-3);
  EXPECT_TRUE(p.grounded);
  const MassingFeatures& f = r.b.massing.features;
  EXPECT_EQ(f.tiers, 1);
  EXPECT_EQ(f.edges, 0);
  EXPECT_EQ(f.courtyards, 0);
  EXPECT_FALSE(f.tower_on_podium);
  // As attributes: the Building and its parts.
  const json& a = r.b.feature.objects.at("B").at("attributes");
  EXPECT_EQ(a.at("morphcut_tiers"), 1);
  EXPECT_EQ(a.at("morphcut_massing_level"), 0.01);
  const json& pa = r.b.feature.objects.at("B-mc1-0").at("attributes");
  EXPECT_EQ(pa.at("morphcut_role"), "main");
  EXPECT_EQ(pa.at("morphcut_grounded"), true);
  EXPECT_NEAR(pa.at("morphcut_footprint_area").get<double>(), 120, 1e-6);
}

// An L of one height under one flat roof is one mass, as the people who labelled real buildings
// see it (docs/massing.md, "The labelled set"): two parts, one main mass, no wing.
TEST(Massing, LShapeOfOneHeightIsOneMainMass) {
  const Result r = run(prism({{0, 0, 0}, {20, 0, 0}, {20, 10, 0}, {10, 10, 0}, {10, 20, 0}, {0, 20, 0}}, 8));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  EXPECT_EQ(r.roles, (Roles{{"main", 2}})) << describe(r);
  EXPECT_EQ(r.level->masses.size(), 1u);
  EXPECT_EQ(r.b.massing.features.wings, 0);
  ASSERT_EQ(r.level->parts.size(), 2u);
  // One side contact, 10 m x 8 m.
  ASSERT_EQ(r.level->parts[0].contacts.size(), 1u);
  EXPECT_EQ(r.level->parts[0].contacts[0].kind, "side");
  EXPECT_NEAR(r.level->parts[0].contacts[0].area, 80, 1e-3);
  EXPECT_EQ(r.b.massing.features.edges, 1);
  EXPECT_EQ(r.b.massing.features.cycles, 0);
}

// An L whose arm is lower (5 m against 8 m) is a main mass and a wing.
TEST(Massing, LShapeWithALowerArmIsMainAndWing) {
  const Result r = run(join({box({0, 0, 0}, {20, 10, 8}), box({0, 10, 0}, {10, 20, 5})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  EXPECT_EQ(r.roles, (Roles{{"main", 1}, {"wing", 1}})) << describe(r);
  EXPECT_EQ(r.level->masses.size(), 2u);
  EXPECT_EQ(r.b.massing.features.wings, 1);
}

TEST(Massing, HouseWithPorchIsMainAndAnnex) {
  const Result r = run(join({gable_house(12, 10, 4, 8), box({4, -3, 0}, {8, 0, 3})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  EXPECT_EQ(r.roles, (Roles{{"main", 1}, {"annex", 1}})) << describe(r);
  EXPECT_EQ(r.b.massing.features.annexes, 1);
}

TEST(Massing, PodiumWithTower) {
  const Result r = run(join({box({0, 0, 0}, {30, 30, 6}), box({9, 9, 6}, {21, 21, 36})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  EXPECT_EQ(r.roles, (Roles{{"podium", 1}, {"tower", 1}})) << describe(r);
  EXPECT_TRUE(r.b.massing.features.tower_on_podium);
  EXPECT_EQ(r.b.massing.features.tiers, 2);
  // The stacked contact: the tower's base, 12 x 12, the tower above.
  for (const auto& p : r.level->parts)
    if (p.role == "tower") {
      ASSERT_EQ(p.contacts.size(), 1u);
      EXPECT_EQ(p.contacts[0].kind, "stacked");
      EXPECT_EQ(p.contacts[0].above, 1);
      EXPECT_NEAR(p.contacts[0].area, 144, 1e-3);
      EXPECT_FALSE(p.grounded);
    }
}

TEST(Massing, SteppedBlockHasFourTiersAndThreeSetbacks) {
  const Result r = run(join({box({0, 0, 0}, {30, 30, 6}), box({3, 3, 6}, {27, 27, 12}),
                             box({6, 6, 12}, {24, 24, 18}), box({9, 9, 18}, {21, 21, 24})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  EXPECT_EQ(r.b.massing.features.tiers, 4) << describe(r);
  EXPECT_EQ(r.b.massing.features.setbacks, 3) << describe(r);
  EXPECT_EQ(r.roles, (Roles{{"main", 1}, {"setback", 3}})) << describe(r);
}

TEST(Massing, PerimeterBlockAroundACourtyard) {
  const Result r = run(join({box({0, 0, 0}, {40, 12, 10}), box({0, 28, 0}, {40, 40, 10}),
                             box({0, 12, 0}, {12, 28, 10}), box({28, 12, 0}, {40, 28, 10})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  EXPECT_EQ(r.b.massing.features.courtyards, 1) << describe(r);
  EXPECT_GE(r.b.massing.features.cycles, 1) << describe(r);
  // The building footprint: one polygon with the court as its hole.
  ASSERT_EQ(r.b.massing.footprint.size(), 1u);
  ASSERT_EQ(r.b.massing.footprint[0].size(), 2u);
}

TEST(Massing, GableHouseWithTwoDormers) {
  // Ridge along x at y = 5, z = 8; the south slope z = 4 + 0.8 y. Dormers: flat roof at 7.4,
  // front wall at y = 1.5 (slope 5.2), boxes reaching down into the house.
  Result r = run(join({gable_house(14, 10, 4, 8), box({2, 1.5, 4.5}, {5.5, 4.25, 7.4}),
                       box({8.5, 1.5, 4.5}, {12, 4.25, 7.4})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  EXPECT_EQ(r.b.massing.features.rooftop_units, 2) << describe(r);
  EXPECT_EQ(r.roles["rooftop"], 2) << describe(r);
  EXPECT_EQ(r.roles["main"], 1) << describe(r);
}

// A 0.6 m skin on the lower half of one wall: a layer of the block's mass, never an annex.
TEST(Massing, WallSkinIsALayerOfTheMainMass) {
  const Result r = run(join({box({0, 0, 0}, {12, 10, 8}), box({0, -0.6, 0}, {12, 0, 4})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  ASSERT_TRUE(r.level);
  ASSERT_EQ(r.level->parts.size(), 2u) << describe(r);
  EXPECT_EQ(r.level->masses.size(), 1u) << describe(r);
  EXPECT_EQ(r.roles, (Roles{{"main", 2}})) << describe(r);
  EXPECT_EQ(r.b.massing.features.annexes, 0);
  EXPECT_EQ(r.b.massing.features.wings, 0);
  int layers = 0;
  for (const auto& p : r.level->parts) layers += p.piece == "layer";
  EXPECT_EQ(layers, 1) << describe(r);
  const json& a = r.b.feature.objects.at("B-mc1-0").at("attributes");
  EXPECT_EQ(a.at("morphcut_mass"), 0);
}

// One storey carrying a storey 13 m long, 3.6 m deep and 5 m high: a setback, not a tower on a
// podium (taller than wide, but not taller than long; docs/massing.md, "Roles").
TEST(Massing, StoreyOnABaseIsASetbackNotATower) {
  const Result r = run(join({box({0, 0, 0}, {20, 8, 4}), box({3, 2, 4}, {16, 5.6, 9})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  EXPECT_EQ(r.roles, (Roles{{"main", 1}, {"setback", 1}})) << describe(r);
  EXPECT_FALSE(r.b.massing.features.tower_on_podium);
  EXPECT_EQ(r.b.massing.features.setbacks, 1);
  EXPECT_EQ(r.b.massing.features.tiers, 2);
}

// A block whose upper floor overhangs the lower one on one side: the lower storey is covered by the
// upper one, which is flush with the full-height block beside it: one mass, not a wing under a
// setback (docs/massing.md, "Masses", step 6).
TEST(Massing, StoreyUnderAnOverhangingFloorIsOneMass) {
  const Result r =
      run(join({box({0, 0, 0}, {10, 10, 8}), box({10, 0, 0}, {20, 10, 4}), box({10, -2, 4}, {22, 10, 8})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  ASSERT_TRUE(r.level);
  EXPECT_GE(r.level->parts.size(), 2u) << describe(r);
  EXPECT_EQ(r.level->masses.size(), 1u) << describe(r);
  EXPECT_EQ(r.b.massing.features.tiers, 1) << describe(r);
  EXPECT_EQ(r.b.massing.features.wings + r.b.massing.features.setbacks, 0) << describe(r);
}

// A 1.5 m deep gallery along a whole façade, up to 7 m of the block's 8 m: a façade zone, a layer of
// the block's mass. The same strip 3 m high is a lean-to: an annex.
TEST(Massing, FacadeZoneIsALayerAndALowStripAnAnnex) {
  const Result zone = run(join({box({0, 0, 0}, {12, 10, 8}), box({0, -1.5, 0}, {12, 0, 7})}));
  ASSERT_EQ(zone.b.status, "ok") << zone.b.reason;
  ASSERT_TRUE(zone.level);
  ASSERT_EQ(zone.level->parts.size(), 2u) << describe(zone);
  EXPECT_EQ(zone.level->masses.size(), 1u) << describe(zone);
  EXPECT_EQ(zone.roles, (Roles{{"main", 2}})) << describe(zone);
  const Result lean = run(join({box({0, 0, 0}, {12, 10, 8}), box({0, -1.5, 0}, {12, 0, 3})}));
  ASSERT_EQ(lean.b.status, "ok") << lean.b.reason;
  ASSERT_TRUE(lean.level);
  EXPECT_EQ(lean.level->masses.size(), 2u) << describe(lean);
  EXPECT_EQ(lean.b.massing.features.annexes, 1) << describe(lean);
}

// An upper storey on a base with a low 1.6 m strip along its whole side on the same floor (a terrace
// edge, the foot of a mansard): raised, the strip is a layer of the storey, not a rooftop unit,
// though it rises only to the storey's lower half (docs/massing.md, "Masses", step 1).
TEST(Massing, LowStripBesideAnUpperStoreyIsALayerOfIt) {
  const Result r = run(join(
      {box({0, 0, 0}, {20, 20, 11}), box({2, 2, 11}, {18, 16, 15.4}), box({2, 16, 11}, {18, 17.6, 13})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  ASSERT_TRUE(r.level);
  ASSERT_EQ(r.level->parts.size(), 3u) << describe(r);
  EXPECT_EQ(r.level->masses.size(), 2u) << describe(r);
  EXPECT_EQ(r.roles, (Roles{{"main", 1}, {"setback", 2}})) << describe(r);
  EXPECT_EQ(r.b.massing.features.rooftop_units, 0) << describe(r);
  EXPECT_EQ(r.b.massing.features.setbacks, 1) << describe(r);
}

// Two flat blocks side by side whose tops differ by 0.8 m: one mass when they are 19 m tall (a
// small step for the height, mass_height_share), two when they are 6 m tall.
TEST(Massing, SmallStepOnATallBlockIsOneMass) {
  const Result tall = run(join({box({0, 0, 0}, {10, 10, 19}), box({10, 0, 0}, {20, 10, 18.2})}));
  ASSERT_EQ(tall.b.status, "ok") << tall.b.reason;
  ASSERT_TRUE(tall.level);
  ASSERT_EQ(tall.level->parts.size(), 2u) << describe(tall);
  EXPECT_EQ(tall.level->masses.size(), 1u) << describe(tall);
  const Result low = run(join({box({0, 0, 0}, {10, 10, 6}), box({10, 0, 0}, {20, 10, 5.2})}));
  ASSERT_EQ(low.b.status, "ok") << low.b.reason;
  ASSERT_TRUE(low.level);
  ASSERT_EQ(low.level->parts.size(), 2u) << describe(low);
  EXPECT_EQ(low.level->masses.size(), 2u) << describe(low);
}

// A wing on a slope: its GroundSurface is 3 m above the main block's. It stands on the ground (the
// input says so), not on a part: a wing, not a setback.
TEST(Massing, WingOnHigherGroundIsGrounded) {
  const Result r = run(join({box({0, 0, 0}, {10, 10, 12}), box({10, 0, 3}, {20, 10, 9})}));
  ASSERT_EQ(r.b.status, "ok") << r.b.reason;
  ASSERT_TRUE(r.level);
  EXPECT_EQ(r.roles, (Roles{{"main", 1}, {"wing", 1}})) << describe(r);
  EXPECT_EQ(r.b.massing.features.wings, 1) << describe(r);
  EXPECT_EQ(r.b.massing.features.setbacks, 0) << describe(r);
}

// A gable house whose south slope runs on over a 2 m strip beside it (the footprint juts out at
// one corner): the decomposition cuts the strip off, lower than the ridge (9.2 against 11 m) with
// its roof in the south slope's plane. A slice of the house, one mass (slice_of); the same strip
// as a flat-roofed box of that height is an annex.
TEST(Massing, SliceUnderTheSlopeIsOneMassAndABoxBesideItAnAnnex) {
  using mc::test::add_face;
  using mc::test::add_vertex;
  PolygonMesh m;
  const uint32_t g0 = add_vertex(m, {0, 0, 0}), g1 = add_vertex(m, {12, 0, 0}),
                 g2 = add_vertex(m, {12, 2, 0}), g3 = add_vertex(m, {10, 2, 0}),
                 g4 = add_vertex(m, {10, 10, 0}), g5 = add_vertex(m, {0, 10, 0});
  const uint32_t t0 = add_vertex(m, {0, 0, 8}), t1 = add_vertex(m, {12, 0, 8}),
                 t2 = add_vertex(m, {12, 2, 9.2}), t3 = add_vertex(m, {10, 2, 9.2}),
                 t4 = add_vertex(m, {10, 10, 8}), t5 = add_vertex(m, {0, 10, 8});
  const uint32_t r0 = add_vertex(m, {0, 5, 11}), r1 = add_vertex(m, {10, 5, 11});
  add_face(m, {g0, g5, g4, g3, g2, g1}, "GroundSurface");
  add_face(m, {g0, g1, t1, t0}, "WallSurface");
  add_face(m, {g1, g2, t2, t1}, "WallSurface");
  add_face(m, {g2, g3, t3, t2}, "WallSurface");
  add_face(m, {g3, g4, t4, r1, t3}, "WallSurface");
  add_face(m, {g4, g5, t5, t4}, "WallSurface");
  add_face(m, {g5, g0, t0, r0, t5}, "WallSurface");
  add_face(m, {t0, t1, t2, t3, r1, r0}, "RoofSurface");
  add_face(m, {r0, r1, t4, t5}, "RoofSurface");
  const Result slice = run(m);
  ASSERT_EQ(slice.b.status, "ok") << slice.b.reason;
  ASSERT_TRUE(slice.level);
  ASSERT_EQ(slice.level->parts.size(), 2u) << describe(slice);
  EXPECT_EQ(slice.level->masses.size(), 1u) << describe(slice);
  EXPECT_EQ(slice.b.massing.features.annexes, 0) << describe(slice);
  const Result box_beside = run(join({gable_house(10, 10, 8, 11), box({10, 0, 0}, {12, 2, 9.2})}));
  ASSERT_EQ(box_beside.b.status, "ok") << box_beside.b.reason;
  ASSERT_TRUE(box_beside.level);
  EXPECT_EQ(box_beside.b.massing.features.annexes, 1) << describe(box_beside);
}

// Cached outcomes carry the analytics exactly.
TEST(Massing, JsonRoundTrip) {
  const Result r = run(join({box({0, 0, 0}, {30, 30, 6}), box({9, 9, 6}, {21, 21, 36})}));
  BuildingMassing back;
  massing_from_json(massing_to_json(r.b.massing), back);
  EXPECT_EQ(massing_to_json(back).dump(), massing_to_json(r.b.massing).dump());
  EXPECT_EQ(graph_json("B", "ok", back).dump(), graph_json("B", "ok", r.b.massing).dump());
}

}  // namespace
}  // namespace mc::pipeline
