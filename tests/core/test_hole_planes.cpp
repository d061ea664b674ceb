// Planes of the holes of an open input (core/hole_planes.hpp).
#include "core/hole_planes.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace mc
