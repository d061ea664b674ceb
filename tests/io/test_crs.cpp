// CRS -> WGS84 with PROJ, offline. Debian's proj-data lacks the Dutch RDNAPTRANS grids, so
// PROJ uses a grid-free Helmert (about 1 m); tolerances allow for that but catch datum errors
// (Bessel vs WGS84 is about 100 m in the Netherlands).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>
#include <vector>

#include "io/crs.hpp"
#include "io/reproject.hpp"

using mc::io::CrsTransformer;

namespace {

// Distance in metres between two lon/lat points (equirectangular; fine at metre scale).
double metres(double lon1, double lat1, double lon2, double lat2) {
  constexpr double R = 6371000, d2r = M_PI / 180;
  const double x = (lon2 - lon1) * d2r * std::cos((lat1 + lat2) / 2 * d2r);
  const double y = (lat2 - lat1) * d2r;
  return R * std::hypot(x, y);
}

// Independent reference: the published RD -> WGS84 approximation polynomials (Schreutelkamp &
// Strang van Hees, "Benaderingsformules voor de transformatie tussen RD- en WGS84-
// kaartcoördinaten", decimeter-level), so PROJ is not tested against itself.
std::pair<double, double> rd_to_wgs84_approx(double x, double y) {
  const double dx = (x - 155000) * 1e-5, dy = (y - 463000) * 1e-5;
  struct T {
    int p, q;
    double c;
  };
  const T K[] = {{0, 1, 3235.65389}, {2, 0, -32.58297}, {0, 2, -0.24750}, {2, 1, -0.84978},
                 {0, 3, -0.06550},   {2, 2, -0.01709},  {1, 0, -0.00738}, {4, 0, 0.00530},
                 {2, 3, -0.00039},   {4, 1, 0.00033},   {1, 1, -0.00012}};
  const T L[] = {{1, 0, 5260.52916}, {1, 1, 105.94684}, {1, 2, 2.45656},  {3, 0, -0.81885},
                 {1, 3, 0.05594},    {3, 1, -0.05607},  {0, 1, 0.01199},  {3, 2, -0.00256},
                 {1, 4, 0.00128},    {0, 2, 0.00022},   {2, 0, -0.00022}, {5, 0, 0.00026}};
  double lat = 0, lon = 0;
  for (const T& t : K) lat += t.c * std::pow(dx, t.p) * std::pow(dy, t.q);
  for (const T& t : L) lon += t.c * std::pow(dx, t.p) * std::pow(dy, t.q);
  return {5.38720621 + lon / 3600, 52.15517440 + lat / 3600};
}

TEST(Crs, Normalize) {
  EXPECT_EQ(mc::io::normalize_crs("https://www.opengis.net/def/crs/EPSG/0/7415"), "EPSG:7415");
  EXPECT_EQ(mc::io::normalize_crs("http://www.opengis.net/def/crs/EPSG/0/28992"), "EPSG:28992");
  EXPECT_EQ(mc::io::normalize_crs("urn:ogc:def:crs:EPSG::28992"), "EPSG:28992");
  EXPECT_EQ(mc::io::normalize_crs("urn:ogc:def:crs:EPSG:9.8.1:2056"), "EPSG:2056");
  EXPECT_EQ(mc::io::normalize_crs("epsg:4326"), "EPSG:4326");
  EXPECT_EQ(mc::io::normalize_crs("+proj=longlat +datum=WGS84"), "+proj=longlat +datum=WGS84");
}

TEST(Crs, EmptyAndUnknownAreInvalid) {
  const CrsTransformer none("");
  EXPECT_FALSE(none.valid());
  EXPECT_FALSE(none.to_lonlat(155000, 463000, 0));
  const CrsTransformer bad("EPSG:99999999");
  EXPECT_FALSE(bad.valid());
  EXPECT_FALSE(bad.error().empty());
}

TEST(Crs, AmersfoortInRdNew) {
  for (const char* id :
       {"EPSG:28992", "urn:ogc:def:crs:EPSG::28992", "https://www.opengis.net/def/crs/EPSG/0/28992"}) {
    const CrsTransformer t(id);
    ASSERT_TRUE(t.valid()) << id << ": " << t.error();
    const auto ll = t.to_lonlat(155000, 463000, 0);
    ASSERT_TRUE(ll) << id;
    EXPECT_LT(metres(ll->first, ll->second, 5.38720621, 52.15517440), 2.0)
        << id << " " << ll->first << " " << ll->second;
  }
}

TEST(Crs, CompoundRdNapGivesTheSameLonLat) {
  const CrsTransformer rd("EPSG:28992"), rdnap("https://www.opengis.net/def/crs/EPSG/0/7415");
  ASSERT_TRUE(rdnap.valid()) << rdnap.error();
  const auto a = rd.to_lonlat(85346.297, 446973.358, 0);
  const auto b = rdnap.to_lonlat(85346.297, 446973.358, 25.0);  // height must not matter
  ASSERT_TRUE(a && b);
  EXPECT_LT(metres(a->first, a->second, b->first, b->second), 0.01);
}

TEST(Crs, DelftPointFrom3dBag) {
  const std::string path =
      MC_SOURCE_DIR "/../shared/datasets/cityjson/upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20.city.json";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  const nlohmann::json j = nlohmann::json::parse(in);
  const auto& s = j["transform"]["scale"];
  const auto& tr = j["transform"]["translate"];
  const CrsTransformer t(j["metadata"]["referenceSystem"].get<std::string>());
  ASSERT_TRUE(t.valid()) << t.error();
  int checked = 0;
  for (std::size_t i = 0; i < j["vertices"].size(); i += 997) {
    const auto& v = j["vertices"][i];
    const double x = v[0].get<double>() * s[0].get<double>() + tr[0].get<double>();
    const double y = v[1].get<double>() * s[1].get<double>() + tr[1].get<double>();
    const double z = v[2].get<double>() * s[2].get<double>() + tr[2].get<double>();
    const auto ll = t.to_lonlat(x, y, z);
    ASSERT_TRUE(ll);
    EXPECT_NEAR(ll->first, 4.36, 0.05);
    EXPECT_NEAR(ll->second, 52.0, 0.05);
    const auto ref = rd_to_wgs84_approx(x, y);
    EXPECT_LT(metres(ll->first, ll->second, ref.first, ref.second), 2.0) << x << " " << y;
    ++checked;
  }
  EXPECT_GT(checked, 5);
}

TEST(Crs, GeographicInputPassesThrough) {
  const CrsTransformer t("EPSG:4326");  // EPSG axis order is lat, lon; we take x = lon
  ASSERT_TRUE(t.valid());
  const auto ll = t.to_lonlat(4.36, 52.0, 0);
  ASSERT_TRUE(ll);
  EXPECT_NEAR(ll->first, 4.36, 1e-9);
  EXPECT_NEAR(ll->second, 52.0, 1e-9);
}

TEST(Crs, NonFiniteInputIsRejected) {
  const CrsTransformer t("EPSG:28992");
  EXPECT_FALSE(t.to_lonlat(NAN, 463000, 0));
}

TEST(Crs, ConcurrentUseGivesIdenticalResults) {
  const CrsTransformer t("EPSG:7415");
  const auto expect = t.to_lonlat(85000, 447000, 0);
  ASSERT_TRUE(expect);
  std::vector<std::thread> ts;
  std::atomic<int> mismatches{0};
  for (int k = 0; k < 4; ++k)
    ts.emplace_back([&] {
      for (int i = 0; i < 2000; ++i) {
        const auto r = t.to_lonlat(85000, 447000, i);
        if (!r || r->first != expect->first || r->second != expect->second) ++mismatches;
      }
    });
  for (auto& th : ts) th.join();
  EXPECT_EQ(mismatches.load(), 0);
}

TEST(Crs, MovedTransformerStillWorks) {
  CrsTransformer a("EPSG:28992");
  CrsTransformer b = std::move(a);
  ASSERT_TRUE(b.valid());
  EXPECT_TRUE(b.to_lonlat(155000, 463000, 0));
  EXPECT_FALSE(a.valid());  // NOLINT(bugprone-use-after-move): documented moved-from state
}

}  // namespace

TEST(CoordinateSystem, GeographicProjectedFeetAndGeocentricFromPROJ) {
  using K = mc::CoordinateSystem::Kind;
  std::string note;
  // WGS 84 3D and JGD2011 + JGD2011 height (PLATEAU): degrees, latitude first in GML's order.
  for (const char* crs :
       {"EPSG:4979", "https://www.opengis.net/def/crs/EPSG/0/6697", "EPSG:4326", "EPSG:6668"}) {
    SCOPED_TRACE(crs);
    const auto gml = mc::io::coordinate_system(crs, true, &note);
    EXPECT_EQ(gml.kind, K::Geographic);
    EXPECT_TRUE(gml.lat_first);
    EXPECT_EQ(gml.vertical_unit, 1.0);
    EXPECT_FALSE(mc::io::coordinate_system(crs, false, &note).lat_first);  // CityJSON: longitude first
  }
  // RD New + NAP: metres.
  const auto rd = mc::io::coordinate_system("EPSG:7415", false, &note);
  EXPECT_EQ(rd.kind, K::Metric);
  EXPECT_TRUE(rd.metric());
  // NAD83 / New York Long Island (ftUS): feet horizontally, and heights taken in the same unit.
  const auto ny = mc::io::coordinate_system("EPSG:2263", false, &note);
  EXPECT_EQ(ny.kind, K::Scaled);
  EXPECT_NEAR(ny.horizontal_unit, 0.3048006096, 1e-9);
  EXPECT_NEAR(ny.vertical_unit, 0.3048006096, 1e-9);
  // NAD83 / NY Long Island ftUS + NAVD88 height (ftUS).
  const auto ny3 = mc::io::coordinate_system("EPSG:6539+6360", false, &note);
  EXPECT_EQ(ny3.kind, K::Scaled);
  EXPECT_NEAR(ny3.vertical_unit, 0.3048006096, 1e-9);
  EXPECT_EQ(mc::io::coordinate_system("EPSG:4978", false, &note).kind, K::Geocentric);
  // None: metres, silently; unknown: metres, with a note.
  note.clear();
  EXPECT_TRUE(mc::io::coordinate_system("", false, &note).metric());
  EXPECT_TRUE(note.empty());
  EXPECT_TRUE(mc::io::coordinate_system("EPSG:99999999", false, &note).metric());
  EXPECT_NE(note.find("not known to PROJ"), std::string::npos) << note;
}

TEST(Reprojector, RdNewToWgs84AgreesWithThePublishedPolynomialsAndKeepsHeights) {
  const mc::io::Reprojector to_wgs84("EPSG:7415", "EPSG:4979");
  const mc::io::Reprojector back("EPSG:4979", "EPSG:28992");
  std::vector<mc::Vec3> pts = {{85000, 446000, -0.61}, {155000, 463000, 12.5}, {86123.456, 447000.5, 30}};
  const std::vector<mc::Vec3> rd = pts;
  to_wgs84.apply(pts);
  for (size_t i = 0; i < pts.size(); ++i) {
    const auto ref = rd_to_wgs84_approx(rd[i].x, rd[i].y);
    EXPECT_LT(metres(pts[i].x, pts[i].y, ref.first, ref.second), 2.0);  // longitude first
    EXPECT_EQ(pts[i].z, rd[i].z);
  }
  back.apply(pts);  // and back, to the same millimetre
  for (size_t i = 0; i < pts.size(); ++i) {
    EXPECT_NEAR(pts[i].x, rd[i].x, 1e-3);
    EXPECT_NEAR(pts[i].y, rd[i].y, 1e-3);
  }
  EXPECT_THROW(mc::io::Reprojector("EPSG:99999999", "EPSG:4326"), std::runtime_error);
}
