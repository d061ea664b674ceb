// The streaming CityGML reader: the shared 1.0/2.0 samples, small synthetic edge cases (3.0,
// xlinks, holes, 2D and broken coordinates, other city objects, malformed XML), srsName
// normalisation, and that peak memory does not grow with the number of buildings.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <set>

#include "io/citygml_crs.hpp"
#include "io/citygml_reader.hpp"
#include "io/feature_source.hpp"
#include "tests/io/citygml_test_util.hpp"

namespace mc::io::test {
namespace {

using nlohmann::json;

std::string citygml_file(const std::string& name) {
  const std::string local = project_data("citygml/" + name);
  return fs::exists(local) ? local : shared_dir() + "/citygml/" + name;
}

// Every geometry of every object, and checks that its vertex references are in range.
std::vector<json> geometries(const Feature& f) {
  std::vector<json> out;
  for (const auto& [id, obj] : f.objects.items())
    if (obj.contains("geometry"))
      for (const auto& g : obj["geometry"]) out.push_back(g);
  return out;
}

// Surfaces (arrays of rings) of a geometry, whatever its type.
void collect_surfaces(const json& b, int depth, std::vector<json>& out) {
  if (depth == 0) {
    out.push_back(b);
    return;
  }
  for (const auto& c : b) collect_surfaces(c, depth - 1, out);
}
std::vector<json> surfaces(const json& g) {
  const std::string t = g["type"];
  const int depth = t == "MultiSurface" || t == "CompositeSurface" ? 1 : t == "Solid" ? 2 : 3;
  std::vector<json> out;
  collect_surfaces(g["boundaries"], depth, out);
  return out;
}
std::set<std::string> semantic_types(const json& g) {
  std::set<std::string> s;
  if (g.contains("semantics"))
    for (const auto& t : g["semantics"]["surfaces"]) s.insert(t["type"].get<std::string>());
  return s;
}

struct Box {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-lo.x, -lo.y, -lo.z};
  void add(const Vec3& v) {
    lo = {std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = {std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
};

// Every ring has >= 3 distinct in-range vertices and no repeated closing point.
void expect_sound_rings(const Feature& f) {
  for (const auto& g : geometries(f))
    for (const auto& s : surfaces(g))
      for (const auto& ring : s) {
        ASSERT_GE(ring.size(), 3u) << f.id;
        EXPECT_NE(ring.front(), ring.back()) << f.id << ": closing point repeated";
        for (const auto& v : ring) EXPECT_LT(v.get<size_t>(), f.vertices.size()) << f.id;
      }
}

// ---- the shared samples ----

TEST(CityGmlReader, DenHaagV10BuildingWithSixPartsXlinkedSolidsAndSemantics) {
  const auto r = read_gml(citygml_file("DenHaag_1BwBP.citygml1.0.gml"));
  EXPECT_EQ(r.format, "CityGML 1.0");
  EXPECT_EQ(r.header.version, "2.0");
  EXPECT_EQ(r.header.crs, "EPSG:28992");
  EXPECT_EQ(r.header.root["metadata"]["referenceSystem"], "https://www.opengis.net/def/crs/EPSG/0/28992");
  EXPECT_EQ(r.header.root["transform"]["translate"], json({78342.0, 457631.0, 3.0}));  // envelope corner
  ASSERT_EQ(r.features.size(), 1u);
  const Feature& f = r.features[0];
  EXPECT_EQ(f.id, "GUID_7F91F413-F839-48F6-A36A-E0F2F090C6B0");
  const json& b = f.objects[f.id];
  EXPECT_EQ(b["type"], "Building");
  ASSERT_EQ(b["children"].size(), 6u);
  for (int i = 1; i <= 6; ++i) {
    const std::string pid = f.id + "_" + std::to_string(i);
    ASSERT_TRUE(f.objects.contains(pid)) << pid;
    const json& p = f.objects[pid];
    EXPECT_EQ(p["type"], "BuildingPart");
    EXPECT_EQ(p["parents"], json::array({f.id}));
    ASSERT_EQ(p["geometry"].size(), 1u) << pid;
    const json& g = p["geometry"][0];
    EXPECT_EQ(g["type"], "Solid");
    EXPECT_EQ(g["lod"], "2");
    // The solid's surfaces are xlinks to the semantic boundary surfaces: all of them labelled.
    EXPECT_TRUE(semantic_types(g).count("RoofSurface")) << pid;
    EXPECT_TRUE(semantic_types(g).count("WallSurface")) << pid;
    for (const auto& v : g["semantics"]["values"][0]) EXPECT_FALSE(v.is_null()) << pid;
    EXPECT_TRUE(p["attributes"]["AbsoluteRidgeHeight"].is_number()) << pid;  // gen:doubleAttribute
  }
  EXPECT_TRUE(f.problems.empty()) << f.problems.front();
  Box box;
  for (const auto& v : f.vertices) box.add(v);
  // Inside the file's envelope (78342.805 457631.26 3.003 - 79020.651 458246.858 37.481).
  EXPECT_GE(box.lo.x, 78342.8);
  EXPECT_LE(box.hi.x, 79020.7);
  EXPECT_GE(box.lo.z, 3.0);
  EXPECT_LE(box.hi.z, 37.5);
  expect_sound_rings(f);
}

TEST(CityGmlReader, Lod2BuildingsV20BoundarySurfacesAndTypedAttributes) {
  const std::string path = shared_dir() + "/citygml/LOD2_Buildings_v200.gml";
  if (!fs::exists(path)) GTEST_SKIP() << path << " not found";
  const auto r = read_gml(path);
  EXPECT_EQ(r.format, "CityGML 2.0");
  EXPECT_EQ(r.header.crs, "");  // no srsName anywhere
  ASSERT_EQ(r.features.size(), 100u);
  std::set<std::string> ids;
  for (const auto& f : r.features) {
    ids.insert(f.id);
    ASSERT_EQ(f.objects.size(), 1u);
    const json& b = f.objects[f.id];
    ASSERT_EQ(b["geometry"].size(), 1u);
    const json& g = b["geometry"][0];
    EXPECT_EQ(g["type"], "MultiSurface");       // boundary surfaces only, no solid
    EXPECT_EQ(surfaces(g).size(), 7u) << f.id;  // ground, 4 walls, 2 roof planes
    EXPECT_EQ(semantic_types(g), (std::set<std::string>{"GroundSurface", "WallSurface", "RoofSurface"}));
    EXPECT_EQ(f.vertices.size(), 10u) << f.id;  // a gable house, shared corners pooled
    expect_sound_rings(f);
  }
  EXPECT_EQ(ids.size(), 100u);
  const json& a = r.features[0].objects[r.features[0].id]["attributes"];
  EXPECT_EQ(a["yearOfConstruction"], 1929);
  EXPECT_EQ(a["measuredHeight"], 11.0);
  EXPECT_EQ(a["storeysAboveGround"], 5);
  EXPECT_EQ(a["name"], "Testcase-0-0_LoD2");
  EXPECT_EQ(a["roofType"], "1030");
}

TEST(CityGmlReader, CompositeSolidOfXlinksWithAFlippedSharedSurface) {
  const auto r = read_gml(citygml_file("b1_lod2_cs_w_sem.gml"));
  ASSERT_EQ(r.features.size(), 1u);
  const Feature& f = r.features[0];
  EXPECT_EQ(f.id, "building-1");  // no gml:id: named by its position in the file
  const json& gs = f.objects[f.id]["geometry"];
  ASSERT_EQ(gs.size(), 1u);  // the lod2Solid; the lod2MultiSurface it reuses is not doubled
  const json& g = gs[0];
  EXPECT_EQ(g["type"], "CompositeSolid");
  ASSERT_EQ(g["boundaries"].size(), 2u);
  const json& a = g["boundaries"][0][0];
  const json& b = g["boundaries"][1][0];
  ASSERT_EQ(a.size(), 6u);
  ASSERT_EQ(b.size(), 5u);
  // "internal-ceiling": last surface of solid 1, and through OrientableSurface orientation="-"
  // the first of solid 2, with the opposite orientation.
  std::vector<int64_t> up = a[5][0], down = b[0][0];
  std::reverse(down.begin(), down.end());
  auto rotate_to = [](std::vector<int64_t> v, int64_t first) {
    std::rotate(v.begin(), std::find(v.begin(), v.end(), first), v.end());
    return v;
  };
  EXPECT_EQ(rotate_to(down, up[0]), up);
  EXPECT_EQ(g["semantics"]["values"], json::parse(R"([[[0,1,1,1,1,null]],[[null,2,2,2,2]]])"));
  EXPECT_EQ(semantic_types(g), (std::set<std::string>{"GroundSurface", "WallSurface", "RoofSurface"}));
  EXPECT_EQ(f.vertices.size(), 10u);
  expect_sound_rings(f);
}

TEST(CityGmlReader, SolidOfGmlPosRings) {
  const auto r = read_gml(citygml_file("b1_lod2_s.gml"));
  ASSERT_EQ(r.features.size(), 1u);
  const Feature& f = r.features[0];
  const json& g = f.objects[f.id]["geometry"][0];
  EXPECT_EQ(g["type"], "Solid");
  EXPECT_EQ(surfaces(g).size(), 9u);
  EXPECT_FALSE(g.contains("semantics"));
  EXPECT_EQ(f.vertices.size(), 10u);
  expect_sound_rings(f);
}

TEST(CityGmlReader, BerlinV10RealBuildingsWithHoles) {
  const std::string path = shared_dir() + "/citygml/berlin_open_data_sample_data.citygml1.0.gml";
  if (!fs::exists(path)) GTEST_SKIP() << path << " not found";
  const auto r = read_gml(path);
  EXPECT_EQ(r.header.crs, "EPSG:25833");
  ASSERT_EQ(r.features.size(), 61u);
  size_t holes = 0, polygons = 0;
  for (const auto& f : r.features) {
    EXPECT_TRUE(f.id.rfind("BLDG_", 0) == 0 || f.id.rfind("DEB_LOD2_UUID_", 0) == 0) << f.id;  // gml:ids
    for (const auto& g : geometries(f))
      for (const auto& s : surfaces(g)) {
        ++polygons;
        holes += s.size() - 1;
      }
    for (const auto& v :
         f.vertices) {  // the envelope: 390477.99 5819214.18 27.52 - 390703.08 5819552.65 64.22
      EXPECT_GE(v.x, 390477.9);
      EXPECT_LE(v.x, 390703.1);
      EXPECT_GE(v.y, 5819214.1);
      EXPECT_LE(v.y, 5819552.7);
    }
    expect_sound_rings(f);
  }
  EXPECT_EQ(polygons, 1125u);  // every gml:Polygon of the file
  EXPECT_EQ(holes, 5u);        // every gml:interior
}

// ---- synthetic edge cases ----

class CityGmlSynthetic : public GmlFileTest {};

const char* kHead2 = R"(<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:b="http://www.opengis.net/citygml/building/2.0"
 xmlns:g="http://www.opengis.net/gml" xmlns:xlink="http://www.w3.org/1999/xlink"
 xmlns:gen="http://www.opengis.net/citygml/generics/2.0" xmlns:tran="http://www.opengis.net/citygml/transportation/2.0"
 xmlns:frn="http://www.opengis.net/citygml/cityfurniture/2.0">
)";

std::string cube_polys(double z0 = 0, const std::string& id_prefix = "p") {
  // A unit cube's 6 faces (outward), closed rings as GML writes them.
  const double z1 = z0 + 1;
  auto P = [&](const std::string& id, const std::string& coords) {
    return "<g:surfaceMember><g:Polygon g:id=\"" + id_prefix + id +
           "\"><g:exterior><g:LinearRing><g:posList>" + coords +
           "</g:posList></g:LinearRing></g:exterior></g:Polygon></g:surfaceMember>";
  };
  auto z = [](double v) { return std::to_string(v); };
  return P("b", "0 0 " + z(z0) + " 0 1 " + z(z0) + " 1 1 " + z(z0) + " 1 0 " + z(z0) + " 0 0 " + z(z0)) +
         P("t", "0 0 " + z(z1) + " 1 0 " + z(z1) + " 1 1 " + z(z1) + " 0 1 " + z(z1) + " 0 0 " + z(z1)) +
         P("s", "0 0 " + z(z0) + " 1 0 " + z(z0) + " 1 0 " + z(z1) + " 0 0 " + z(z1) + " 0 0 " + z(z0)) +
         P("e", "1 0 " + z(z0) + " 1 1 " + z(z0) + " 1 1 " + z(z1) + " 1 0 " + z(z1) + " 1 0 " + z(z0)) +
         P("n", "1 1 " + z(z0) + " 0 1 " + z(z0) + " 0 1 " + z(z1) + " 1 1 " + z(z1) + " 1 1 " + z(z0)) +
         P("w", "0 1 " + z(z0) + " 0 0 " + z(z0) + " 0 0 " + z(z1) + " 0 1 " + z(z1) + " 0 1 " + z(z0));
}

TEST_F(CityGmlSynthetic, CityGml3BuildingWithPartBoundaryAndGenericAttribute) {
  const std::string xml = R"(<?xml version="1.0"?>
<CityModel xmlns="http://www.opengis.net/citygml/3.0" xmlns:bldg="http://www.opengis.net/citygml/building/3.0"
 xmlns:con="http://www.opengis.net/citygml/construction/3.0" xmlns:gen="http://www.opengis.net/citygml/generics/3.0"
 xmlns:gml="http://www.opengis.net/gml/3.2" xmlns:xlink="http://www.w3.org/1999/xlink">
 <cityObjectMember><bldg:Building gml:id="B3">
  <genericAttribute><gen:IntAttribute><gen:name>floors</gen:name><gen:value>3</gen:value></gen:IntAttribute></genericAttribute>
  <bldg:function>1000</bldg:function>
  <bldg:buildingPart><bldg:BuildingPart gml:id="B3-P">
   <boundary><con:WallSurface gml:id="W"><lod2MultiSurface><gml:MultiSurface>
    <gml:surfaceMember><gml:Polygon gml:id="wall"><gml:exterior><gml:LinearRing>
     <gml:posList srsDimension="3">0 0 0 1 0 0 1 0 1 0 0 1 0 0 0</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
   </gml:MultiSurface></lod2MultiSurface></con:WallSurface></boundary>
   <lod2Solid><gml:Solid><gml:exterior><gml:Shell>
    <gml:surfaceMember xlink:href="#wall"/>
    <gml:surfaceMember><gml:Polygon><gml:exterior><gml:LinearRing>
     <gml:posList>0 0 1 1 0 1 1 1 1 0 0 1</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
   </gml:Shell></gml:exterior></gml:Solid></lod2Solid>
  </bldg:BuildingPart></bldg:buildingPart>
 </bldg:Building></cityObjectMember>
</CityModel>)";
  const auto r = read_gml(write("v3.gml", xml));
  EXPECT_EQ(r.format, "CityGML 3.0");
  ASSERT_EQ(r.features.size(), 1u);
  const Feature& f = r.features[0];
  EXPECT_EQ(f.objects["B3"]["attributes"]["floors"], 3);
  EXPECT_EQ(f.objects["B3"]["attributes"]["function"], "1000");
  EXPECT_EQ(f.objects["B3"]["children"], json::array({"B3-P"}));
  const json& g = f.objects["B3-P"]["geometry"][0];
  EXPECT_EQ(g["type"], "Solid");
  EXPECT_EQ(g["lod"], "2");
  EXPECT_EQ(g["semantics"]["values"], json::parse("[[0,null]]"));  // the xlinked wall is labelled
  EXPECT_EQ(g["semantics"]["surfaces"][0]["type"], "WallSurface");
  EXPECT_EQ(f.vertices.size(), 5u);  // the wall's 4 corners + the triangle's third (pooled)
}

TEST_F(CityGmlSynthetic, InteriorRingsAndGmlCoordinates) {
  const std::string xml = std::string(kHead2) + R"(<core:cityObjectMember><b:Building g:id="H">
<b:lod2MultiSurface><g:MultiSurface><g:surfaceMember><g:Polygon><g:exterior><g:LinearRing>
 <g:coordinates>0,0,0 10,0,0 10,10,0 0,10,0 0,0,0</g:coordinates></g:LinearRing></g:exterior>
 <g:interior><g:LinearRing><g:posList>2 2 0 2 4 0 4 4 0 4 2 0 2 2 0</g:posList></g:LinearRing></g:interior>
</g:Polygon></g:surfaceMember></g:MultiSurface></b:lod2MultiSurface></b:Building></core:cityObjectMember></core:CityModel>)";
  const auto r = read_gml(write("holes.gml", xml));
  ASSERT_EQ(r.features.size(), 1u);
  const json& g = r.features[0].objects["H"]["geometry"][0];
  EXPECT_EQ(g["type"], "MultiSurface");
  EXPECT_EQ(g["boundaries"], json::parse("[[[0,1,2,3],[4,5,6,7]]]"));
  EXPECT_EQ(r.features[0].vertices[6], (Vec3{4, 4, 0}));
}

TEST_F(CityGmlSynthetic, TwoDimensionalAndBrokenCoordinatesLeaveTheBuildingWithoutGeometryAndAReason) {
  const std::string xml =
      std::string(kHead2) + R"(
<core:cityObjectMember><b:Building g:id="flat"><b:lod2MultiSurface><g:MultiSurface srsDimension="2">
 <g:surfaceMember><g:Polygon><g:exterior><g:LinearRing><g:posList>0 0 1 0 1 1 0 0</g:posList>
 </g:LinearRing></g:exterior></g:Polygon></g:surfaceMember></g:MultiSurface></b:lod2MultiSurface></b:Building></core:cityObjectMember>
<core:cityObjectMember><b:Building g:id="broken"><b:lod2MultiSurface><g:MultiSurface>
 <g:surfaceMember><g:Polygon><g:exterior><g:LinearRing><g:posList>0 0 0 1 0 0 1 1</g:posList>
 </g:LinearRing></g:exterior></g:Polygon></g:surfaceMember></g:MultiSurface></b:lod2MultiSurface></b:Building></core:cityObjectMember>
<core:cityObjectMember><b:Building g:id="nan"><b:lod2MultiSurface><g:MultiSurface>
 <g:surfaceMember><g:Polygon><g:exterior><g:LinearRing><g:posList>0 0 0 1 x 0 1 1 0 0 0 0</g:posList>
 </g:LinearRing></g:exterior></g:Polygon></g:surfaceMember></g:MultiSurface></b:lod2MultiSurface></b:Building></core:cityObjectMember>
<core:cityObjectMember><b:Building g:id="implicit"><b:lod2ImplicitRepresentation/></b:Building></core:cityObjectMember>
<core:cityObjectMember><b:Building g:id="good"><b:lod1Solid><g:Solid><g:exterior><g:CompositeSurface>)" +
      cube_polys() +
      R"(</g:CompositeSurface></g:exterior></g:Solid></b:lod1Solid></b:Building></core:cityObjectMember>
</core:CityModel>)";
  const auto r = read_gml(write("bad.gml", xml));
  ASSERT_EQ(r.features.size(), 5u);  // every building is handed out, usable or not
  auto expect_no_geometry = [](const Feature& f, const std::string& reason) {
    EXPECT_FALSE(f.objects[f.id].contains("geometry")) << f.id;
    EXPECT_TRUE(f.vertices.empty()) << f.id;
    ASSERT_FALSE(f.problems.empty()) << f.id;
    EXPECT_NE(f.problems.front().find(reason), std::string::npos) << f.problems.front();
    EXPECT_EQ(f.problems.front().rfind(f.id + ": ", 0), 0u) << f.problems.front();
  };
  expect_no_geometry(r.features[0], "2D coordinates");
  expect_no_geometry(r.features[1], "broken gml:posList: 8 values");
  expect_no_geometry(r.features[2], "\"x\" is not a number");
  expect_no_geometry(r.features[3], "ImplicitRepresentation");
  EXPECT_TRUE(r.features[4].problems.empty());
  EXPECT_EQ(r.features[4].objects["good"]["geometry"][0]["lod"], "1");
  EXPECT_EQ(r.features[4].vertices.size(), 8u);
}

TEST_F(CityGmlSynthetic, OpeningsAreSemanticSurfacesAndLod4BecomesLod3) {
  auto ms = [](const std::string& lod, const std::string& coords) {
    return "<b:lod" + lod +
           "MultiSurface><g:MultiSurface><g:surfaceMember><g:Polygon><g:exterior><g:LinearRing><g:posList>" +
           coords +
           "</g:posList></g:LinearRing></g:exterior></g:Polygon></g:surfaceMember></g:MultiSurface></b:lod" +
           lod + "MultiSurface>";
  };
  const std::string wall = "0 0 0 4 0 0 4 0 3 0 0 3 0 0 0", window = "1 0 1 2 0 1 2 0 2 1 0 2 1 0 1";
  const std::string xml = std::string(kHead2) + R"(<core:cityObjectMember><b:Building g:id="L3">
<b:boundedBy><b:WallSurface>)" +
                          ms("3", wall) + R"(<b:opening><b:Window>)" + ms("3", window) +
                          R"(</b:Window></b:opening></b:WallSurface></b:boundedBy>)" + ms("4", wall) +
                          R"(</b:Building></core:cityObjectMember>
<core:cityObjectMember><b:Building g:id="L4"><b:lod4Solid><g:Solid><g:exterior><g:CompositeSurface>)" +
                          cube_polys() +
                          R"(</g:CompositeSurface></g:exterior></g:Solid></b:lod4Solid></b:Building>
</core:cityObjectMember></core:CityModel>)";
  const auto r = read_gml(write("lod3.gml", xml));
  ASSERT_EQ(r.features.size(), 2u);
  const Feature& a = r.features[0];
  ASSERT_EQ(a.objects["L3"]["geometry"].size(), 1u);  // lod4 dropped: lod3 exists
  const json& g = a.objects["L3"]["geometry"][0];
  EXPECT_EQ(g["lod"], "3");
  EXPECT_EQ(g["semantics"]["surfaces"], json::parse(R"([{"type":"WallSurface"},{"type":"Window"}])"));
  EXPECT_EQ(g["semantics"]["values"], json::parse("[0,1]"));
  ASSERT_EQ(a.problems.size(), 1u);
  EXPECT_NE(a.problems[0].find("lod4 geometry not carried"), std::string::npos);
  const Feature& b = r.features[1];
  EXPECT_EQ(b.objects["L4"]["geometry"][0]["lod"], "3");  // CityJSON stops at LoD 3
  EXPECT_EQ(b.objects["L4"]["geometry"][0]["type"], "Solid");
}

TEST_F(CityGmlSynthetic, CrsFromTheFirstBuildingWithoutEnvelopeAndDisagreementsReported) {
  auto building = [](const std::string& id, const std::string& srs, double z0) {
    return "<core:cityObjectMember><b:Building g:id=\"" + id + "\"><b:lod2Solid><g:Solid srsName=\"" + srs +
           "\"><g:exterior><g:CompositeSurface>" + cube_polys(z0, id) +
           "</g:CompositeSurface></g:exterior></g:Solid></b:lod2Solid>"
           // A wall beside the solid: not doubled into it, and said so.
           "<b:boundedBy><b:WallSurface><b:lod2MultiSurface><g:MultiSurface><g:surfaceMember><g:Polygon><g:"
           "exterior>"
           "<g:LinearRing><g:posList>5 5 0 6 5 0 6 5 1 5 5 "
           "0</g:posList></g:LinearRing></g:exterior></g:Polygon>"
           "</g:surfaceMember></g:MultiSurface></b:lod2MultiSurface></b:WallSurface></b:boundedBy>"
           "</b:Building></core:cityObjectMember>";
  };
  const std::string xml = std::string(kHead2) + building("a", "urn:ogc:def:crs:EPSG::7415", 10.5) +
                          building("b", "EPSG:28992", 0) + "</core:CityModel>";
  const auto r = read_gml(write("crs.gml", xml));
  EXPECT_EQ(r.header.crs, "EPSG:7415");
  EXPECT_EQ(r.header.root["transform"]["translate"],
            json({0.0, 0.0, 0.0}));  // first building's corner, floored
  ASSERT_EQ(r.features.size(), 2u);
  ASSERT_EQ(r.features[0].problems.size(), 1u);
  EXPECT_EQ(r.features[0].problems[0], "a: 1 lod2 surface(s) outside the lod2Solid not carried");
  ASSERT_EQ(r.problems.size(), 1u);
  EXPECT_NE(
      r.problems[0].find("1 buildings have an srsName other than the file's (b has srsName \"EPSG:28992\")"),
      std::string::npos)
      << r.problems[0];
}

TEST_F(CityGmlSynthetic, UnresolvedXlinkIsNotedAndTheRestKept) {
  const std::string xml = std::string(kHead2) + R"(<core:cityObjectMember><b:Building g:id="X">
<b:lod2MultiSurface><g:MultiSurface>)" +
                          cube_polys() +
                          R"(<g:surfaceMember xlink:href="#elsewhere"/></g:MultiSurface></b:lod2MultiSurface>
</b:Building></core:cityObjectMember></core:CityModel>)";
  const auto r = read_gml(write("xlink.gml", xml));
  ASSERT_EQ(r.features.size(), 1u);
  const Feature& f = r.features[0];
  EXPECT_EQ(surfaces(f.objects["X"]["geometry"][0]).size(), 6u);
  ASSERT_EQ(f.problems.size(), 1u);
  EXPECT_NE(f.problems[0].find("#elsewhere"), std::string::npos);
}

TEST_F(CityGmlSynthetic, OtherCityObjectsAreSkippedAndCounted) {
  const std::string xml = std::string(kHead2) + R"(
<core:cityObjectMember><tran:Road g:id="r1"/></core:cityObjectMember>
<core:cityObjectMember><b:Building g:id="A"/></core:cityObjectMember>
<core:cityObjectMember><frn:CityFurniture g:id="f1"><frn:lod1Geometry/></frn:CityFurniture></core:cityObjectMember>
<core:cityObjectMember><tran:Road g:id="r2"/></core:cityObjectMember>
</core:CityModel>)";
  const auto r = read_gml(write("others.gml", xml));
  ASSERT_EQ(r.features.size(), 1u);
  EXPECT_EQ(r.features[0].id, "A");
  EXPECT_EQ(r.skipped, (std::map<std::string, size_t>{{"CityFurniture", 1}, {"Road", 2}}));
  ASSERT_FALSE(r.problems.empty());
  EXPECT_EQ(r.problems[0], "skipped 3 city objects that are not buildings: 1 CityFurniture, 2 Road");
}

TEST_F(CityGmlSynthetic, MalformedXmlThrowsAfterTheBuildingsBeforeIt) {
  const std::string xml = std::string(kHead2) + R"(
<core:cityObjectMember><b:Building g:id="A"/></core:cityObjectMember>
<core:cityObjectMember><b:Building g:id="B"><b:lod2MultiSurface></b:Building></core:cityObjectMember>
</core:CityModel>)";
  CityGmlReader r(write("malformed.gml", xml));
  Feature f;
  ASSERT_TRUE(r.next(f));
  EXPECT_EQ(f.id, "A");
  try {
    r.next(f);
    FAIL() << "no ReadError";
  } catch (const ReadError& e) {
    EXPECT_NE(std::string(e.what()).find("malformed XML: line "), std::string::npos) << e.what();
  }
}

TEST_F(CityGmlSynthetic, FileLevelErrors) {
  EXPECT_THROW(CityGmlReader(dir_.file("missing.gml")), ReadError);
  EXPECT_THROW(CityGmlReader(write("notxml.gml", "{\"type\": \"CityJSON\"}")), ReadError);
  try {
    CityGmlReader r(write("kml.gml", "<kml xmlns=\"http://www.opengis.net/kml/2.2\"/>"));
    FAIL() << "no ReadError";
  } catch (const ReadError& e) {
    EXPECT_NE(std::string(e.what()).find("not CityGML"), std::string::npos) << e.what();
  }
}

TEST_F(CityGmlSynthetic, GzipInputAndFeatureSourceByExtension) {
  const std::string plain = citygml_file("b1_lod2_cs_w_sem.gml");
  const std::string gz = dir_.file("b1.gml.gz");
  ASSERT_EQ(std::system(("gzip -c '" + plain + "' > '" + gz + "'").c_str()), 0);
  auto src = open_feature_source(gz);
  EXPECT_EQ(src->format(), "CityGML 2.0");
  Feature a, b;
  ASSERT_TRUE(src->next(a));
  CityGmlReader direct(plain);
  ASSERT_TRUE(direct.next(b));
  EXPECT_EQ(a.objects, b.objects);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(open_feature_source(project_data("3dbag/3dbag_b2.city.json"))->format(), "CityJSON");
  EXPECT_EQ(open_feature_source(project_data("3dbag/3dbag_b2.city.jsonl"))->format(), "CityJSONSeq");
  EXPECT_TRUE(is_citygml_path("x.GML"));
  EXPECT_FALSE(is_citygml_path("x.city.json"));
}

TEST(CityGmlCrs, SrsNamesBecomeOgcUrls) {
  const std::string base = "https://www.opengis.net/def/crs/EPSG/0/";
  EXPECT_EQ(citygml::reference_system("EPSG:28992"), base + "28992");
  EXPECT_EQ(citygml::reference_system("urn:ogc:def:crs:EPSG::28992"), base + "28992");
  EXPECT_EQ(citygml::reference_system("urn:ogc:def:crs:EPSG:6.12:3068"), base + "3068");
  EXPECT_EQ(citygml::reference_system("http://www.opengis.net/def/crs/EPSG/0/25833"), base + "25833");
  EXPECT_EQ(citygml::reference_system("urn:ogc:def:crs,crs:EPSG::25832,crs:EPSG::7837"), base + "25832");
  EXPECT_EQ(citygml::reference_system("urn:adv:crs:ETRS89_UTM32*DHHN92"), base + "5555");
  EXPECT_EQ(citygml::reference_system("urn:adv:crs:ETRS89_UTM33*DHHN2016"), base + "25833");
  EXPECT_EQ(citygml::reference_system("urn:adv:crs:DE_DHDN_3GK3*DHHN92"), base + "31467");
  EXPECT_EQ(citygml::reference_system("local"), "");
}

// ---- streaming memory ----

// Peak RSS (MB) of reading `path` in a child process, and the number of buildings read.
std::pair<double, size_t> peak_rss_of_reading(const std::string& path) {
  int fds[2];
  if (pipe(fds) != 0) return {-1, 0};
  const pid_t pid = fork();
  if (pid == 0) {
    close(fds[0]);
    double out[2] = {-1, 0};
    try {
      CityGmlReader r(path);
      Feature f;
      size_t n = 0;
      while (r.next(f)) ++n;
      rusage u{};
      getrusage(RUSAGE_SELF, &u);
      out[0] = static_cast<double>(u.ru_maxrss) / 1024.0;
      out[1] = static_cast<double>(n);
    } catch (...) {}
    if (write(fds[1], out, sizeof out) != sizeof out) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  double in[2] = {-1, 0};
  const bool ok = read(fds[0], in, sizeof in) == sizeof in;
  close(fds[0]);
  waitpid(pid, nullptr, 0);
  return ok ? std::make_pair(in[0], static_cast<size_t>(in[1])) : std::make_pair(-1.0, size_t(0));
}

TEST(CityGmlStreaming, PeakMemoryDoesNotGrowWithTheNumberOfBuildings) {
  ScratchDir dir;
  const std::string gen = std::string(MC_SOURCE_DIR) + "/tools/gen_citygml.py";
  std::map<int, std::pair<double, size_t>> peak;
  for (int n : {2000, 20000}) {
    const std::string file = dir.file("city_" + std::to_string(n) + ".gml");
    ASSERT_EQ(std::system(("python3 '" + gen + "' " + std::to_string(n) + " '" + file + "'").c_str()), 0);
    peak[n] = peak_rss_of_reading(file);
    fs::remove(file);
    ASSERT_EQ(peak[n].second, static_cast<size_t>(n));
  }
  // 10x the buildings (about 120 MB of XML): the same few MB.
  EXPECT_LT(peak[20000].first, peak[2000].first + 2.0)
      << peak[2000].first << " MB vs " << peak[20000].first << " MB";
}

}  // namespace
}  // namespace mc::io::test
