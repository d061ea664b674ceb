// Real-world CityGML dialects the reader takes leniently, each deviation said in problems(): an
// unqualified root CityModel, ADE content (PLATEAU's uro:), GML surface patches and orientable
// surfaces, srsName only on buildings or geometries, or nowhere.
#include <gtest/gtest.h>

#include "tests/io/citygml_test_util.hpp"

namespace mc::io::test {
namespace {

using nlohmann::json;

class CityGmlDialects : public GmlFileTest {};

bool has_problem(const GmlRead& r, const std::string& text) {
  for (const auto& p : r.problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

TEST_F(CityGmlDialects, UnqualifiedRootAndMembersAreReadWithWarnings) {
  const auto r = read_gml(gml_test_data("unqualified_root.gml"));
  EXPECT_EQ(r.format, "CityGML 2.0");
  EXPECT_EQ(r.header.crs, "EPSG:25832");  // the envelope (gml:, qualified) is read as usual
  ASSERT_EQ(r.features.size(), 2u);
  EXPECT_EQ(r.features[0].id, "U1");
  EXPECT_EQ(r.features[1].id, "U2");
  EXPECT_EQ(r.features[0].objects["U1"]["attributes"]["measuredHeight"], 1.0);
  EXPECT_EQ(r.features[0].objects["U1"]["geometry"][0]["type"], "Solid");
  EXPECT_EQ(r.features[1].vertices.size(), 8u);
  EXPECT_EQ(r.building_count, 2u);
  ASSERT_EQ(r.problems.size(), 2u) << joined(r.problems);
  EXPECT_EQ(r.problems[0],
            "the root element CityModel has no namespace: read as CityGML 2.0, the version of the CityGML "
            "namespaces declared on it (http://www.opengis.net/citygml/building/2.0)");
  EXPECT_EQ(r.problems[1],
            "read 2 children of CityModel without a namespace as CityGML/GML members and envelope: 2 "
            "cityObjectMember");
}

TEST_F(CityGmlDialects, UnqualifiedRootTakesTheVersionOfItsModuleNamespaces) {
  auto file = [](const std::string& namespaces, const std::string& building_ns) {
    return "<CityModel " + namespaces + R"( xmlns:gml="http://www.opengis.net/gml">
 <boundedBy><gml:Envelope srsName="EPSG:28992"><gml:lowerCorner>1 2 3</gml:lowerCorner></gml:Envelope></boundedBy>
 <featureMember><bldg:Building xmlns:bldg=")" +
           building_ns + R"(" gml:id="a"/></featureMember>
 <gml:featureMembers><bldg:Building xmlns:bldg=")" +
           building_ns + R"(" gml:id="b"/><bldg:Building xmlns:bldg=")" + building_ns +
           R"(" gml:id="c"/></gml:featureMembers>
</CityModel>)";
  };
  const std::string v1 = "http://www.opengis.net/citygml/building/1.0";
  const auto r1 = read_gml(write("v1.gml", file("xmlns:bldg=\"" + v1 + "\"", v1)));
  EXPECT_EQ(r1.format, "CityGML 1.0");
  ASSERT_EQ(r1.features.size(), 3u);  // featureMember and gml:featureMembers (several objects) alike
  EXPECT_EQ(r1.features[2].id, "c");
  EXPECT_EQ(r1.building_count, 3u);
  EXPECT_EQ(r1.header.crs, "EPSG:28992");  // from the unqualified boundedBy
  EXPECT_TRUE(has_problem(r1,
                          "read 2 children of CityModel without a namespace as CityGML/GML members and "
                          "envelope: 1 boundedBy, 1 featureMember"))
      << joined(r1.problems);

  const std::string v3 = "http://www.opengis.net/citygml/building/3.0";
  const auto r3 = read_gml(write(
      "v3.gml",
      file("xmlns:bldg=\"" + v3 + "\" xmlns:con=\"http://www.opengis.net/citygml/construction/3.0\"", v3)));
  EXPECT_EQ(r3.format, "CityGML 3.0");
  EXPECT_EQ(r3.features.size(), 3u);

  // A file mixing versions is read as the version most of its namespaces have, and said so.
  const auto mixed =
      read_gml(write("mixed.gml", file("xmlns:bldg=\"" + v3 +
                                           "\" xmlns:a=\"http://www.opengis.net/citygml/2.0\" "
                                           "xmlns:b=\"http://www.opengis.net/citygml/generics/2.0\"",
                                       v3)));
  EXPECT_EQ(mixed.format, "CityGML 2.0");
  EXPECT_TRUE(
      has_problem(mixed, "the root element declares CityGML namespaces of 2 versions; read as CityGML 2.0"))
      << joined(mixed.problems);
}

TEST_F(CityGmlDialects, UnqualifiedRootWithoutCityGmlNamespacesIsRefused) {
  const std::string path = write("plain.gml", R"(<CityModel xmlns:gml="http://www.opengis.net/gml">
 <cityObjectMember><Building gml:id="a"/></cityObjectMember></CityModel>)");
  try {
    CityGmlReader r(path);
    FAIL() << "no ReadError";
  } catch (const ReadError& e) {
    EXPECT_NE(
        std::string(e.what()).find(
            "not CityGML: the root element is {}CityModel (no namespace) and declares no CityGML namespace"),
        std::string::npos)
        << e.what();
  }
}

TEST_F(CityGmlDialects, AdeElementsAreSkippedAndCountedPerNamespaceAndElement) {
  const auto r = read_gml(gml_test_data("ade_plateau.gml"));
  ASSERT_EQ(r.features.size(), 2u);
  // The buildings are read as without the ADE: attributes, parts, geometry and semantics.
  const Feature& a = r.features[0];
  EXPECT_EQ(a.objects["bldg_1"]["attributes"], json({{"measuredHeight", 1.0}}));
  EXPECT_EQ(a.objects["bldg_1"]["geometry"][0]["type"], "Solid");
  const Feature& b = r.features[1];
  EXPECT_EQ(b.objects["bldg_2"]["children"], json::array({"bldg_2_part"}));
  const json& g = b.objects["bldg_2_part"]["geometry"][0];
  EXPECT_EQ(g["semantics"]["surfaces"], json::parse(R"([{"type":"RoofSurface"}])"));
  EXPECT_TRUE(a.problems.empty()) << joined(a.problems);
  EXPECT_TRUE(b.problems.empty()) << joined(b.problems);
  EXPECT_TRUE(r.skipped.empty());  // the top-level ADE object is counted as ADE, not as a city object
  ASSERT_EQ(r.problems.size(), 1u) << joined(r.problems);
  EXPECT_EQ(r.problems[0],
            "skipped 6 ADE elements: 3 uro:buildingDetailAttribute, 1 urf:UseDistrict, 1 "
            "uro:buildingDisasterRiskAttribute, 1 uro:buildingIDAttribute (urf = "
            "https://www.geospatial.jp/iur/urf/2.0, uro = https://www.geospatial.jp/iur/uro/2.0)");
}

TEST_F(CityGmlDialects, SurfacePatchesAndOrientableSurfacesReversedAlsoThroughXlinks) {
  const auto r = read_gml(gml_test_data("surface_patches.gml"));
  ASSERT_EQ(r.features.size(), 1u);
  const Feature& f = r.features[0];
  EXPECT_TRUE(f.problems.empty()) << joined(f.problems);
  const json& gs = f.objects["P"]["geometry"];
  ASSERT_EQ(gs.size(), 2u);
  EXPECT_EQ(gs[0]["lod"], "1");
  EXPECT_EQ(gs[1]["lod"], "2");
  const json& lod2 = gs[1]["boundaries"];
  ASSERT_EQ(lod2.size(), 4u);  // the Surface's two patches, the reversed Polygon, the xlinked one
  EXPECT_EQ(ring_points(f, lod2[0][0]), (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}));
  EXPECT_EQ(ring_points(f, lod2[1][0]), (std::vector<Vec3>{{0, 0, 0}, {1, 1, 0}, {0, 1, 0}}));
  // orientation="-": the base surface's ring reversed (0 0 5, 1 0 5, 1 1 5, 0 1 5 as written).
  EXPECT_EQ(ring_points(f, lod2[2][0]), (std::vector<Vec3>{{0, 1, 5}, {1, 1, 5}, {1, 0, 5}, {0, 0, 5}}));
  // The lod1 OrientableSurface of a Surface patch, reached by xlink:href: reversed too.
  const std::vector<Vec3> reversed_patch{{1, 1, 7}, {1, 0, 7}, {0, 0, 7}};
  EXPECT_EQ(ring_points(f, lod2[3][0]), reversed_patch);
  EXPECT_EQ(ring_points(f, gs[0]["boundaries"][0][0]), reversed_patch);
}

TEST_F(CityGmlDialects, SrsNameOnTheBuildingOrOnlyOnEachGeometry) {
  const std::string head = R"(<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0"
 xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:gml="http://www.opengis.net/gml">)";
  auto building = [](const std::string& id, const std::string& building_srs, const std::string& polygon_srs) {
    auto srs = [](const std::string& s) { return s.empty() ? std::string() : " srsName=\"" + s + "\""; };
    return "<core:cityObjectMember><bldg:Building gml:id=\"" + id + "\"" + srs(building_srs) +
           "><bldg:lod2MultiSurface><gml:MultiSurface>"
           "<gml:surfaceMember><gml:Polygon" +
           srs(polygon_srs) +
           "><gml:exterior><gml:LinearRing><gml:posList>0 0 0 1 0 0 1 1 0 0 0 "
           "0</gml:posList></gml:LinearRing>"
           "</gml:exterior></gml:Polygon></gml:surfaceMember>"
           "<gml:surfaceMember><gml:Polygon" +
           srs(polygon_srs) +
           "><gml:exterior><gml:LinearRing><gml:posList>0 0 1 1 0 1 1 1 1 0 0 "
           "1</gml:posList></gml:LinearRing>"
           "</gml:exterior></gml:Polygon></gml:surfaceMember>"
           "</gml:MultiSurface></bldg:lod2MultiSurface></bldg:Building></core:cityObjectMember>";
  };
  // Only on each geometry, and the first building has none: the first pass finds it.
  const auto on_geometry =
      read_gml(write("geometry.gml",
                     head + building("none", "", "") + building("g", "", "EPSG:7415") + "</core:CityModel>"));
  EXPECT_EQ(on_geometry.header.crs, "EPSG:7415");
  EXPECT_TRUE(on_geometry.problems.empty()) << joined(on_geometry.problems);

  // Only on the buildings; a building whose geometries disagree with the file is counted once.
  const auto on_building = read_gml(
      write("building.gml", head + building("a", "EPSG:28992", "") + building("b", "EPSG:28992", "") +
                                building("c", "", "EPSG:4326") + "</core:CityModel>"));
  EXPECT_EQ(on_building.header.crs, "EPSG:28992");
  ASSERT_EQ(on_building.problems.size(), 1u) << joined(on_building.problems);
  EXPECT_EQ(
      on_building.problems[0],
      "1 buildings have an srsName other than the file's (c has srsName \"EPSG:4326\"); coordinates are used "
      "as they are");

  // None anywhere: a warning.
  const auto none =
      read_gml(write("none.gml", head + building("a", "", "") + building("b", "", "") + "</core:CityModel>"));
  EXPECT_EQ(none.header.crs, "");
  EXPECT_EQ(none.features.size(), 2u);
  EXPECT_EQ(none.problems,
            std::vector<std::string>{
                "no srsName in the file: coordinates are taken as they are (a metric CRS is assumed)"});
}

}  // namespace
}  // namespace mc::io::test
