// Planes of the holes of an open input (core/hole_planes.hpp).
#include "core/hole_planes.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "core/soup.hpp"
#include "synthetic_buildings.hpp"

namespace mc {
namespace {

PolygonMesh without_face(PolygonMesh m, size_t f) {
  m.faces.erase(m.faces.begin() + static_cast<long>(f));
  return m;
}

TEST(HolePlanes, ClosedBoxHasNone) {
  EXPECT_TRUE(hole_planes(test::box({0, 0, 0}, {4, 3, 2}), 0.01, 0.01, 0).empty());
}

TEST(HolePlanes, MissingWallGivesItsPlane) {
  // box(): faces are the 4 walls (first: y = 0), then floor and roof.
  const PolygonMesh m = without_face(test::box({0, 0, 0}, {4, 3, 2}), 0);
  const auto holes = hole_planes(m, 0.01, 0.01, 0);
  ASSERT_EQ(holes.size(), 1u);
  EXPECT_NEAR(std::abs(holes[0].plane.n.y), 1.0, 1e-12);
  EXPECT_NEAR(holes[0].plane.signed_distance({1, 0, 1}), 0.0, 1e-12);
  EXPECT_NEAR(holes[0].area, 8.0, 1e-9);
  EXPECT_NEAR(holes[0].bbox.hi.x - holes[0].bbox.lo.x, 4.0, 1e-12);
}

TEST(HolePlanes, OpenBottomSmallAndNonPlanarHolesAreLeftOut) {
  // The open bottom lies in the lowest level: the ground plane caps it, not a hole plane.
  EXPECT_TRUE(hole_planes(test::l_prism(false), 0.01, 0.01, 0).empty());
  // A hole below the area limit.
  const PolygonMesh m = without_face(test::box({0, 0, 0}, {4, 3, 2}), 0);
  EXPECT_TRUE(hole_planes(m, 0.01, 9.0, 0).empty());
  // Two adjacent missing walls: one bent boundary loop, not planar.
  const PolygonMesh two = without_face(without_face(test::box({0, 0, 0}, {4, 3, 2}), 1), 0);
  EXPECT_TRUE(hole_planes(two, 0.01, 0.01, 0).empty());
  // Loose faces (every edge a boundary edge of its own face): each face is a "hole" loop only
  // if it were planar and alone; two faces sharing a vertex make a non-simple component.
  PolygonMesh bow;
  for (Vec3 v : {Vec3{0, 0, 1}, Vec3{1, 0, 1}, Vec3{1, 1, 1}, Vec3{2, 1, 1}, Vec3{2, 2, 1}})
    test::add_vertex(bow, v);
  test::add_face(bow, {0, 1, 2}, "RoofSurface");
  test::add_face(bow, {2, 3, 4}, "RoofSurface");
  EXPECT_TRUE(hole_planes(bow, 0.01, 0.01, 0).empty());
}

// Walls that stop 0.3 m above their ground (variant (e) of the open-model generator, docs/algorithm.md
// §6.4): the loop along the walls' lower edges is the top of a gap, not a missing horizontal face.
// A horizontal plane there would cut every cell of the building at the walls' lower edge.
TEST(HolePlanes, GapBetweenWallsAndGroundIsNotAHorizontalFace) {
  PolygonMesh m = test::box({0, 0, 0.3}, {4, 3, 3});  // walls and roof from 0.3 m; its floor removed below
  m.faces.erase(std::find_if(m.faces.begin(), m.faces.end(),
                             [&](const Polygon& f) { return f.semantic == m.label_index("GroundSurface"); }));
  std::vector<uint32_t> ground;
  for (Vec3 v : {Vec3{0, 0, 0}, Vec3{0, 3, 0}, Vec3{4, 3, 0}, Vec3{4, 0, 0}})
    ground.push_back(test::add_vertex(m, v));
  test::add_face(m, ground, "GroundSurface");
  // Two loops: the ground's outline (in the lowest level: capped by the ground plane) and the
  // walls' lower edges (the gap's top): neither is a hole plane.
  EXPECT_TRUE(hole_planes(m, 0.01, 0.01, 0).empty());

  // Without the ground below, the walls' lower edges are an open bottom above the lowest level
  // (the roof of a lower neighbour part is lower still): the plane caps it, a floor.
  PolygonMesh bottom = test::box({0, 0, 0.3}, {4, 3, 3});
  bottom.faces.erase(std::find_if(bottom.faces.begin(), bottom.faces.end(), [&](const Polygon& f) {
    return f.semantic == bottom.label_index("GroundSurface");
  }));
  const auto floors = hole_planes(bottom, 0.01, 0.01, -1.0);
  ASSERT_EQ(floors.size(), 1u);
  EXPECT_NEAR(std::abs(floors[0].plane.n.z), 1.0, 1e-12);
  EXPECT_NEAR(floors[0].plane.signed_distance({1, 1, 0.3}), 0.0, 1e-12);

  // A missing flat roof over a ground: its walls lie below the loop, so it is a missing face.
  PolygonMesh roofless = test::box({0, 0, 0}, {4, 3, 3});
  roofless.faces.erase(std::find_if(roofless.faces.begin(), roofless.faces.end(), [&](const Polygon& f) {
    return f.semantic == roofless.label_index("RoofSurface");
  }));
  const auto roof = hole_planes(roofless, 0.01, 0.01, 0);
  ASSERT_EQ(roof.size(), 1u);
  EXPECT_NEAR(roof[0].plane.signed_distance({1, 1, 3}), 0.0, 1e-12);
}

}  // namespace
}  // namespace mc
