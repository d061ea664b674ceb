// The metric working frame of a building (core/working_frame.hpp): degrees, earth-centred and
// foot coordinates mapped to metres and back. GeographicLib's geodesic distance (an independent
// computation on the same ellipsoid) is the reference for lengths.
#include <gtest/gtest.h>

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/Geodesic.hpp>

#include <cmath>
#include <vector>

#include "core/working_frame.hpp"

using mc::CoordinateSystem;
using mc::Vec3;
using mc::WorkingFrame;

namespace {

CoordinateSystem geographic(bool lat_first = false) {
  CoordinateSystem cs;
  cs.kind = CoordinateSystem::Kind::Geographic;
  cs.lat_first = lat_first;
  return cs;
}

double geodesic(double lat1, double lon1, double lat2, double lon2) {
  double s = 0;
  GeographicLib::Geodesic::WGS84().Inverse(lat1, lon1, lat2, lon2, s);
  return s;
}

}  // namespace

TEST(WorkingFrame, MetricFilesAreTheIdentity) {
  const WorkingFrame f(CoordinateSystem{}, {{85000, 446000, 1}});
  EXPECT_TRUE(f.identity());
  const Vec3 p{85012.345, 446001.5, 7.25};
  EXPECT_EQ(f.to_metric(p), p);
  EXPECT_EQ(f.to_file(p), p);
}

TEST(WorkingFrame, DegreesBecomeTrueMetresAroundTheBuilding) {
  // A PLATEAU-like building in Tokyo: longitude first as CityJSON writes it.
  const std::vector<Vec3> pts = {{139.7670, 35.6810, 30}, {139.7680, 35.6820, 60}};
  const WorkingFrame f(geographic(), pts);
  EXPECT_FALSE(f.identity());
  EXPECT_NEAR(f.origin_lat(), 35.6815, 1e-12);
  EXPECT_NEAR(f.origin_lon(), 139.7675, 1e-12);
  const Vec3 a = f.to_metric(pts[0]), b = f.to_metric(pts[1]);
  // Horizontal distance against the geodesic: the frame's scale error is ~x²/2R² (< 1e-8 here).
  const double flat = std::hypot(b.x - a.x, b.y - a.y);
  const double reference = geodesic(35.6810, 139.7670, 35.6820, 139.7680);
  EXPECT_NEAR(flat / reference, 1.0, 2e-8) << flat << " vs " << reference;
  EXPECT_EQ(a.z, 30);  // heights are kept
  EXPECT_EQ(b.z, 60);
  // The origin is the building's centre: its coordinates are metres near zero.
  EXPECT_LT(std::abs(a.x), 60);
  EXPECT_LT(std::abs(a.y), 60);
  // Round trip to far below the 1e-8 degree output grid.
  for (const Vec3& p : pts) {
    const Vec3 q = f.to_file(f.to_metric(p));
    EXPECT_NEAR(q.x, p.x, 1e-11);
    EXPECT_NEAR(q.y, p.y, 1e-11);
    EXPECT_EQ(q.z, p.z);
  }
}

TEST(WorkingFrame, NorthIsUpTheYAxisAndAFlatRoofStaysFlat) {
  const std::vector<Vec3> pts = {{4.37, 52.0, 0}};
  const WorkingFrame f(geographic(), pts);
  const Vec3 o = f.to_metric({4.37, 52.0, 10}), n = f.to_metric({4.37, 52.001, 10}),
             e = f.to_metric({4.371, 52.0, 10});
  EXPECT_NEAR(n.x - o.x, 0, 1e-9);  // the central meridian is the y axis
  EXPECT_GT(n.y - o.y, 100);
  EXPECT_NEAR(e.y - o.y, 0, 1e-2);  // 68 m east: the parallel curves by ~0.5 mm only
  EXPECT_GT(e.x - o.x, 60);
  EXPECT_EQ(o.z, 10);  // constant ellipsoidal height: constant z (a tangent plane would bend it)
  EXPECT_EQ(e.z, 10);
}

TEST(WorkingFrame, AVolumeIsTheSameInDegreesAsInMetres) {
  // A 20 m x 10 m x 6 m box laid out with the geodesic: its volume in the frame is 1200 m³.
  const double lat = -33.92, lon = 18.42;  // Cape Town: southern and eastern hemisphere
  double lat_n = 0, lon_n = 0, lat_e = 0, lon_e = 0;
  GeographicLib::Geodesic::WGS84().Direct(lat, lon, 0, 10, lat_n, lon_n);
  GeographicLib::Geodesic::WGS84().Direct(lat, lon, 90, 20, lat_e, lon_e);
  const std::vector<Vec3> pts = {{lon, lat, 0}, {lon_e, lat_n, 6}};
  const WorkingFrame f(geographic(), pts);
  const Vec3 a = f.to_metric({lon, lat, 0}), b = f.to_metric({lon_e, lat, 0}),
             c = f.to_metric({lon, lat_n, 0});
  EXPECT_NEAR(std::hypot(b.x - a.x, b.y - a.y), 20, 1e-6);
  EXPECT_NEAR(std::hypot(c.x - a.x, c.y - a.y), 10, 1e-6);
}

TEST(WorkingFrame, LatitudeFirstIsReadAsDeclaredOrSwappedWhenOutOfRange) {
  // Declared latitude first, written latitude first (GML): read as such.
  const WorkingFrame gml(geographic(true), {{35.68, 139.76, 0}});
  EXPECT_FALSE(gml.swapped());
  EXPECT_NEAR(gml.origin_lat(), 35.68, 1e-12);
  // Declared longitude first but the "latitudes" are 139°: the file wrote latitude first.
  const WorkingFrame swapped(geographic(false), {{35.68, 139.76, 0}});
  EXPECT_TRUE(swapped.swapped());
  EXPECT_NEAR(swapped.origin_lat(), 35.68, 1e-12);
  const Vec3 p{35.681, 139.761, 5};
  const Vec3 q = swapped.to_file(swapped.to_metric(p));
  EXPECT_NEAR(q.x, p.x, 1e-11);  // written back in the file's own order
  EXPECT_NEAR(q.y, p.y, 1e-11);
}

TEST(WorkingFrame, EarthCentredCoordinatesGetAVerticalZ) {
  CoordinateSystem cs;
  cs.kind = CoordinateSystem::Kind::Geocentric;
  const auto& g = GeographicLib::Geocentric::WGS84();
  Vec3 ground, roof, east;
  g.Forward(47.37, 8.54, 400, ground.x, ground.y, ground.z);
  g.Forward(47.37, 8.54, 425, roof.x, roof.y, roof.z);
  g.Forward(47.37, 8.5401, 400, east.x, east.y, east.z);
  const WorkingFrame f(cs, {ground, roof, east});
  const Vec3 a = f.to_metric(ground), b = f.to_metric(roof), c = f.to_metric(east);
  EXPECT_NEAR(b.x - a.x, 0, 1e-7);
  EXPECT_NEAR(b.y - a.y, 0, 1e-7);
  EXPECT_NEAR(b.z - a.z, 25, 1e-7);  // up is z
  EXPECT_NEAR(c.z, a.z, 1e-7);
  const Vec3 back = f.to_file(b);
  EXPECT_NEAR(back.x, roof.x, 1e-6);
  EXPECT_NEAR(back.y, roof.y, 1e-6);
  EXPECT_NEAR(back.z, roof.z, 1e-6);
}

TEST(WorkingFrame, FeetAreScaledToMetres) {
  CoordinateSystem cs;
  cs.kind = CoordinateSystem::Kind::Scaled;
  cs.horizontal_unit = cs.vertical_unit = 0.3048006096012192;  // US survey foot
  const WorkingFrame f(cs, {{987000, 211000, 30}});
  const Vec3 m = f.to_metric({1000, 2000, 100});
  EXPECT_DOUBLE_EQ(m.x, 304.8006096012192);
  EXPECT_DOUBLE_EQ(m.z, 30.48006096012192);
  const Vec3 back = f.to_file(m);
  EXPECT_NEAR(back.x, 1000, 1e-9);
  EXPECT_NEAR(back.z, 100, 1e-9);
}
