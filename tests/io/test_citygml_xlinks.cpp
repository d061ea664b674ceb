// The first pass (citygml_prescan) and what it enables: the building count before reading, and
// xlinks to surfaces anywhere in the file (another building, a non-building object, before or
// after the building), stored by a bounded extra pass (citygml_remote).
#include <gtest/gtest.h>
#include <libxml/parser.h>

#include <fstream>

#include "io/citygml_building.hpp"
#include "io/citygml_remote.hpp"
#include "io/citygml_xml.hpp"
#include "tests/io/citygml_test_util.hpp"

namespace mc::io::test {
namespace {

using nlohmann::json;

// The exterior rings of a feature's first geometry (a Solid), as points.
std::vector<std::vector<Vec3>> solid_faces(const Feature& f) {
  std::vector<std::vector<Vec3>> out;
  const json& g = f.objects[f.id]["geometry"].at(0);
  EXPECT_EQ(g["type"], "Solid") << f.id;
  for (const auto& surface : g["boundaries"][0]) out.push_back(ring_points(f, surface[0]));
  return out;
}
// The face whose points all have this x.
std::vector<Vec3> face_at_x(const Feature& f, double x) {
  for (const auto& face : solid_faces(f))
    if (std::all_of(face.begin(), face.end(), [&](const Vec3& p) { return p.x == x; })) return face;
  return {};
}

TEST(CityGmlXlinks, SurfacesSharedBetweenBuildingsResolveAnywhereInTheFile) {
  const auto r = read_gml(gml_test_data("remote_xlinks.gml"));
  EXPECT_EQ(r.building_count, 4u);
  ASSERT_EQ(r.features.size(), 4u);
  for (const auto& f : r.features) {
    EXPECT_TRUE(f.problems.empty()) << f.id << ": " << joined(f.problems);
    EXPECT_EQ(solid_faces(f).size(), 6u) << f.id;
  }
  EXPECT_EQ(r.skipped, (std::map<std::string, size_t>{{"GenericCityObject", 1}}));
  EXPECT_EQ(r.problems.size(), 1u) << joined(r.problems);  // the skipped GenericCityObject
  const Feature &a = r.features[0], &b = r.features[1], &c = r.features[2], &d = r.features[3];
  const std::vector<Vec3> a_east{{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}};
  EXPECT_EQ(face_at_x(a, 1), a_east);
  // B: A's east wall through an OrientableSurface "-" outside both buildings, which itself refers
  // back into A (found by a second store pass): reversed.
  EXPECT_EQ(face_at_x(b, 1), std::vector<Vec3>(a_east.rbegin(), a_east.rend()));
  // C: a polygon of D, later in the file, as it is; D uses it reversed.
  const std::vector<Vec3> cd{{3, 0, 0}, {3, 1, 0}, {3, 1, 1}, {3, 0, 1}};
  EXPECT_EQ(face_at_x(c, 3), cd);
  EXPECT_EQ(face_at_x(d, 3), std::vector<Vec3>(cd.rbegin(), cd.rend()));
}

TEST(CityGmlXlinks, ATargetKeepsTheSrsDimensionOfItsAncestorsAndAMissingOneIsNamed) {
  ScratchDir dir;
  const std::string path = dir.file("flat.gml");
  std::ofstream(path) << R"(<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0"
 xmlns:bldg="http://www.opengis.net/citygml/building/2.0" xmlns:gen="http://www.opengis.net/citygml/generics/2.0"
 xmlns:gml="http://www.opengis.net/gml" xmlns:xlink="http://www.w3.org/1999/xlink">
 <core:cityObjectMember><gen:GenericCityObject><gen:lod2Geometry><gml:MultiSurface srsDimension="2">
  <gml:surfaceMember><gml:Polygon gml:id="flat"><gml:exterior><gml:LinearRing><gml:posList>0 0 1 0 1 1 0 0</gml:posList>
  </gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember></gml:MultiSurface></gen:lod2Geometry></gen:GenericCityObject>
 </core:cityObjectMember>
 <core:cityObjectMember><bldg:Building gml:id="E"><bldg:lod2MultiSurface><gml:MultiSurface>
  <gml:surfaceMember xlink:href="#flat"/></gml:MultiSurface></bldg:lod2MultiSurface></bldg:Building></core:cityObjectMember>
 <core:cityObjectMember><bldg:Building gml:id="F"><bldg:lod2MultiSurface><gml:MultiSurface>
  <gml:surfaceMember xlink:href="#nowhere"/></gml:MultiSurface></bldg:lod2MultiSurface></bldg:Building></core:cityObjectMember>
</core:CityModel>)";
  const auto r = read_gml(path);
  ASSERT_EQ(r.features.size(), 2u);
  // Read with srsDimension 2 from the MultiSurface around it: 2D, refused as such (without it,
  // its 8 values would be a broken 3D posList).
  ASSERT_FALSE(r.features[0].problems.empty());
  EXPECT_EQ(
      r.features[0].problems[0],
      "E: 2D coordinates (srsDimension 2 in gml:posList) are not supported; the building's geometry is not "
      "read");
  EXPECT_EQ(
      r.features[1].problems,
      std::vector<std::string>{"F: xlink:href \"#nowhere\" names no element of this building and no GML "
                               "geometry elsewhere in the file; that surface is missing"});
}

// The first element of this name and gml:id in a tree.
const xmlNode* find_element(const xmlNode* n, std::string_view name, const std::string& id) {
  if (gmlxml::local(n) == name && gmlxml::gml_id(n) == id) return n;
  for (const xmlNode* c = gmlxml::first_child(n); c; c = gmlxml::next_sibling(c))
    if (const xmlNode* found = find_element(c, name, id)) return found;
  return nullptr;
}

TEST(CityGmlXlinks, TheStoreIsBoundedAndSaysWhatItLeftOut) {
  const std::string path = gml_test_data("remote_xlinks.gml");
  citygml::RemoteGeometry all;
  all.collect(path, {"A-east", "CD"});
  EXPECT_EQ(all.elements(), 2u);
  EXPECT_TRUE(all.problems().empty());

  // Room for one polygon (5 nodes at 250 bytes and its text): the first in the file is stored.
  citygml::RemoteGeometry small;
  small.collect(path, {"A-east", "CD"}, 1500);
  EXPECT_EQ(small.elements(), 1u);
  EXPECT_NE(small.find("A-east"), nullptr);
  EXPECT_EQ(small.find("CD"), nullptr);
  EXPECT_TRUE(small.dropped("CD"));
  ASSERT_EQ(small.problems().size(), 1u);
  EXPECT_NE(small.problems()[0].find("is full"), std::string::npos) << small.problems()[0];
  EXPECT_NE(small.problems()[0].find("1 more are not stored"), std::string::npos) << small.problems()[0];

  // A building that needs the dropped one says why its wall is missing.
  xmlDocPtr doc = xmlReadFile(path.c_str(), nullptr, XML_PARSE_NONET);
  ASSERT_NE(doc, nullptr);
  const xmlNode* c = find_element(xmlDocGetRootElement(doc), "Building", "C");
  ASSERT_NE(c, nullptr);
  const auto converted = citygml::convert_building(c, "C", &small);
  xmlFreeDoc(doc);
  ASSERT_EQ(converted.feature.problems.size(), 1u);
  EXPECT_EQ(
      converted.feature.problems[0],
      "C: xlink:href \"#CD\" names geometry outside this building that is not stored (the store of such "
      "targets is full); that surface is missing");
}

TEST(CityGmlXlinks, BuildingCountIsWhatTheReaderHandsOut) {
  for (const std::string name : {"DenHaag_1BwBP.citygml1.0.gml", "LOD2_Buildings_v200_first10.gml",
                                 "b1_lod2_s.gml", "b1_lod2_cs_w_sem.gml"}) {
    const auto r = read_gml(project_data("citygml/" + name));
    EXPECT_EQ(r.building_count, r.features.size()) << name;
  }
  const std::string berlin = shared_dir() + "/citygml/berlin_open_data_sample_data.citygml1.0.gml";
  if (fs::exists(berlin)) { EXPECT_EQ(read_gml(berlin).building_count, 61u); }

  // The first pass meets the XML error: the count is not known (next() throws where it is).
  ScratchDir dir;
  const std::string bad = dir.file("bad.gml");
  {
    // Enough good buildings before the bad one that the parser has not reached it yet when the
    // first is handed out.
    std::ofstream out(bad);
    out << R"(<CityModel xmlns="http://www.opengis.net/citygml/2.0" xmlns:b="http://www.opengis.net/citygml/building/2.0">)";
    for (int i = 0; i < 500; ++i) out << "<cityObjectMember><b:Building/></cityObjectMember>\n";
    out << "<cityObjectMember><b:Building></cityObjectMember></CityModel>";
  }
  CityGmlReader r(bad);
  EXPECT_EQ(r.feature_count(), std::nullopt);
  Feature f;
  EXPECT_TRUE(r.next(f));
  auto read_on = [&] {
    while (r.next(f)) {}
  };
  EXPECT_THROW(read_on(), ReadError);
}

}  // namespace
}  // namespace mc::io::test
