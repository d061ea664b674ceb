// extract_building on real and hand-made data: LoD selection, BuildingParts, semantics, holes,
// inner shells, templates, and the 3D BAG tile's known quirks.
#include <set>

#include "io_test_util.hpp"

namespace mc::io::test {
namespace {

std::map<std::string, BuildingInput> buildings_of(const std::string& path,
                                                  const std::string& lod = "highest") {
  const auto w = read_all(path);
  std::map<std::string, BuildingInput> out;
  for (const auto& f : w.features)
    if (is_building(f)) out[f.id] = extract_building(f, w.header, lod);
  return out;
}

size_t count_problems_containing(const BuildingInput& b, const std::string& text) {
  size_t n = 0;
  for (const auto& p : b.problems) n += p.find(text) != std::string::npos;
  return n;
}

TEST(ExtractBuilding, The3dBagTileHas432BuildingsWithSemantics) {
  const auto w = read_all(project_data("3dbag/3dbag_5910.city.json"));
  EXPECT_EQ(w.header.version, "2.0");
  EXPECT_EQ(w.header.crs, "EPSG:7415");
  EXPECT_TRUE(w.problems.empty()) << joined(w.problems);
  ASSERT_EQ(w.features.size(), 432u);
  const auto& extent = w.header.root["metadata"]["geographicalExtent"];
  size_t empty = 0, with_holes = 0, with_degenerate = 0, faces = 0;
  const std::set<std::string> no_geometry = {
      "NL.IMBAG.Pand.0503100000032915", "NL.IMBAG.Pand.0503100000033670", "NL.IMBAG.Pand.0503100000033683"};
  for (const auto& f : w.features) {
    SCOPED_TRACE(f.id);
    ASSERT_TRUE(is_building(f));
    const auto b = extract_building(f, w.header);
    if (b.mesh.faces.empty()) {
      ++empty;
      EXPECT_TRUE(no_geometry.count(f.id));
      EXPECT_EQ(b.problems, (std::vector<std::string>{f.id + ": building has no surface geometry"}));
      continue;
    }
    EXPECT_EQ(b.lod, "2.2");
    const std::set<std::string> labels(b.mesh.semantic_labels.begin(), b.mesh.semantic_labels.end());
    EXPECT_TRUE(labels.count("RoofSurface") && labels.count("WallSurface") && labels.count("GroundSurface"));
    bool holes = false;
    for (const auto& face : b.mesh.faces) {
      EXPECT_GE(face.semantic, 0);
      holes |= face.rings.size() > 1;
      for (const auto& ring : face.rings) EXPECT_GE(ring.size(), 3u);
    }
    for (const auto& v : b.mesh.vertices) {  // the transform was applied: real RD coordinates
      EXPECT_GE(v.x, extent[0].get<double>() - 1e-6);
      EXPECT_LE(v.x, extent[3].get<double>() + 1e-6);
      EXPECT_GE(v.y, extent[1].get<double>() - 1e-6);
      EXPECT_LE(v.y, extent[4].get<double>() + 1e-6);
    }
    with_holes += holes;
    with_degenerate += count_problems_containing(b, "fewer than 3 distinct points") > 0;
    faces += b.mesh.faces.size();
  }
  EXPECT_EQ(empty, 3u);
  EXPECT_EQ(with_holes, 31u);      // README: 32 shells with holes, in 31 buildings
  EXPECT_EQ(with_degenerate, 4u);  // README: 4 shells with degenerate rings
  EXPECT_EQ(faces, 21601u);
}

TEST(ExtractBuilding, SequenceTwinGivesTheSameBuildings) {
  const auto doc = buildings_of(project_data("3dbag/3dbag_5910.city.json"));
  const auto seq = buildings_of(project_data("3dbag/3dbag_5910.city.jsonl"));
  ASSERT_EQ(doc.size(), 432u);
  ASSERT_EQ(seq.size(), doc.size());
  for (const auto& [id, b] : doc) {
    SCOPED_TRACE(id);
    const auto it = seq.find(id);
    ASSERT_NE(it, seq.end());
    const auto& s = it->second;
    EXPECT_EQ(b.lod, s.lod);
    EXPECT_EQ(b.mesh.vertices, s.mesh.vertices);
    EXPECT_EQ(b.mesh.semantic_labels, s.mesh.semantic_labels);
    ASSERT_EQ(b.mesh.faces.size(), s.mesh.faces.size());
    for (size_t i = 0; i < b.mesh.faces.size(); ++i) {
      EXPECT_EQ(b.mesh.faces[i].rings, s.mesh.faces[i].rings);
      EXPECT_EQ(b.mesh.faces[i].semantic, s.mesh.faces[i].semantic);
    }
  }
}

TEST(ExtractBuilding, Version11OriginalGivesTheSameBuildingsAsItsUpgrade) {
  if (!have_shared()) GTEST_SKIP() << "no " << shared_dir();
  const auto v11 = buildings_of(shared_dir() + "/cityjson/3dbag/3dbag_v210908_fd2cee53_5910.city.json");
  const auto v20 = buildings_of(project_data("3dbag/3dbag_5910.city.json"));
  ASSERT_EQ(v11.size(), v20.size());
  for (const auto& [id, b] : v20) {
    EXPECT_EQ(v11.at(id).mesh.vertices, b.mesh.vertices) << id;
    EXPECT_EQ(v11.at(id).mesh.faces.size(), b.mesh.faces.size()) << id;
  }
}

TEST(ExtractBuilding, LodSelectionIsExactOrHighest) {
  const auto w = read_all(project_data("edge/multi_lod.city.json"));
  const Feature* f = nullptr;
  for (const auto& e : w.features)
    if (e.id == "6751773") f = &e;
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(building_lods(*f, w.header), (std::vector<std::string>{"1.2", "1.3", "2.2"}));
  const auto high = extract_building(*f, w.header);
  EXPECT_EQ(high.lod, "2.2");
  EXPECT_EQ(high.mesh.faces.size(), 36u);
  const auto l12 = extract_building(*f, w.header, "1.2");
  EXPECT_EQ(l12.lod, "1.2");
  EXPECT_EQ(l12.mesh.faces.size(), 16u);
  EXPECT_TRUE(l12.problems.empty()) << joined(l12.problems);
  const auto none = extract_building(*f, w.header, "2");  // exact: "2" is not "2.2"
  EXPECT_TRUE(none.mesh.empty());
  EXPECT_EQ(none.problems,
            (std::vector<std::string>{"6751773: no usable faces at LoD 2 (available: 1.2, 1.3, 2.2)"}));
}

TEST(ExtractBuilding, PartsCarryTheSolidsAndTheBuildingItsFootprint) {
  const auto w = read_all(project_data("3dbag/delft_subset.city.jsonl"));
  ASSERT_EQ(w.features.size(), 10u);
  const Feature& f = w.features[0];
  EXPECT_EQ(f.id, "NL.IMBAG.Pand.0503100000012869");
  EXPECT_EQ(f.objects.size(), 2u);
  EXPECT_EQ(building_lods(f, w.header), (std::vector<std::string>{"0", "1.2", "1.3", "2.2"}));
  const auto high = extract_building(f, w.header);
  EXPECT_EQ(high.lod, "2.2");
  EXPECT_FALSE(high.mesh.empty());
  const auto foot = extract_building(f, w.header, "0");
  EXPECT_EQ(foot.mesh.faces.size(), 1u);  // the LoD0 MultiSurface of the Building itself
  for (const auto& v : foot.mesh.vertices) EXPECT_EQ(v.z, foot.mesh.vertices[0].z);
}

TEST(ExtractBuilding, InnerShellsAreKept) {
  const auto b = buildings_of(project_data("edge/hollow_solid.city.json"));
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b.begin()->second.mesh.faces.size(), 12u);  // outer cube + void cube
  EXPECT_EQ(b.begin()->second.lod, "2");
}

TEST(ExtractBuilding, StoreysAreNotBuildingParts) {
  if (!have_shared()) GTEST_SKIP() << "no " << shared_dir();
  const auto w = read_all(shared_dir() + "/cityjson/duckdb-cityjson/hierarchy.city.json");
  ASSERT_EQ(w.features.size(), 1u);  // the storeys belong to the building's feature
  EXPECT_EQ(w.features[0].objects.size(), 3u);
  const auto b = extract_building(w.features[0], w.header);
  EXPECT_EQ(b.lod, "2.2");
}

TEST(ExtractBuilding, MultiSolidWithNumericLodOfVersion10) {
  const auto w = read_all(project_data("edge/msol_v10.city.json"));
  EXPECT_EQ(w.header.version, "1.0");
  ASSERT_EQ(w.features.size(), 1u);
  EXPECT_FALSE(is_building(w.features[0]));  // a GenericCityObject; extraction still works
  const auto b = extract_building(w.features[0], w.header);
  EXPECT_EQ(b.lod, "1");
  EXPECT_EQ(b.mesh.faces.size(), 12u);
}

TEST(ExtractBuilding, GeometryInstanceIsResolvedThroughTheTemplates) {
  ScratchDir dir;
  const std::string path = dir.file("instance.city.json");
  std::ofstream(path) << R"({"type":"CityJSON","version":"2.0",
    "transform":{"scale":[0.5,0.5,0.5],"translate":[1000,2000,0]},
    "geometry-templates":{"templates":[{"type":"MultiSurface","lod":"2.2",
        "boundaries":[[[0,1,2,3]],[[0,1,4]]],
        "semantics":{"surfaces":[{"type":"RoofSurface"}],"values":[0,null]}}],
      "vertices-templates":[[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1]]},
    "CityObjects":{
      "b":{"type":"Building","geometry":[{"type":"GeometryInstance","template":0,"boundaries":[0],
        "transformationMatrix":[2,0,0,10, 0,2,0,0, 0,0,2,0, 0,0,0,1]}]},
      "n":{"type":"+NoiseBuilding","geometry":[]}},
    "vertices":[[4,6,8]]})";
  const auto w = read_all(path);
  ASSERT_EQ(w.features.size(), 2u);
  EXPECT_TRUE(is_building(w.features[0]));
  EXPECT_FALSE(is_building(w.features[1]));  // extension types are not buildings
  const auto b = extract_building(w.features[0], w.header);
  EXPECT_TRUE(b.problems.empty()) << joined(b.problems);
  EXPECT_EQ(b.lod, "2.2");
  ASSERT_EQ(b.mesh.faces.size(), 2u);
  ASSERT_EQ(b.mesh.vertices.size(), 5u);
  // template vertex (1,1,0) -> matrix (2*1+10, 2, 0) -> + reference point (1002, 2003, 4)
  EXPECT_EQ(b.mesh.vertices[b.mesh.faces[0].rings[0][2]], mc::Vec3(1014, 2005, 4));
  EXPECT_EQ(b.mesh.semantic_labels, std::vector<std::string>{"RoofSurface"});
  EXPECT_EQ(b.mesh.faces[0].semantic, 0);
  EXPECT_EQ(b.mesh.faces[1].semantic, -1);
}

// A feature built in code (a library user's nlohmann::json) holds its semantic indices as signed
// integers: they are read as the file's unsigned ones are; a negative index is no surface.
TEST(ExtractBuilding, SignedSemanticIndicesOfAFeatureBuiltInCode) {
  ScratchDir dir;
  const std::string path = dir.file("signed.city.json");
  std::ofstream(path) << R"({"type":"CityJSON","version":"2.0",
    "transform":{"scale":[1,1,1],"translate":[0,0,0]},
    "CityObjects":{"b":{"type":"Building","geometry":[{"type":"MultiSurface","lod":"2.2",
        "boundaries":[[[0,1,2,3]],[[0,1,4]]],
        "semantics":{"surfaces":[{"type":"GroundSurface"}],"values":[0,null]}}]}},
    "vertices":[[0,0,0],[1,0,0],[1,1,0],[0,1,0],[0,0,1]]})";
  auto w = read_all(path);
  ASSERT_EQ(w.features.size(), 1u);
  nlohmann::json& values = w.features[0].objects.at("b")["geometry"][0]["semantics"]["values"];
  values = nlohmann::json::array({int{0}, int{-1}});
  ASSERT_TRUE(values[0].is_number_integer() && !values[0].is_number_unsigned());
  const auto b = extract_building(w.features[0], w.header);
  ASSERT_EQ(b.mesh.faces.size(), 2u);
  EXPECT_EQ(b.mesh.faces[0].semantic, 0);
  EXPECT_EQ(b.mesh.faces[1].semantic, -1);
}

}  // namespace
}  // namespace mc::io::test
