// Hausdorff distance between triangle soups.
#include <gtest/gtest.h>

#include <cmath>

#include "core/hausdorff.hpp"
#include "off_fixture.hpp"
#include "synthetic_buildings.hpp"

namespace mc {
namespace {

TEST(Hausdorff, SelfIsZero) {
  const TriangleSoup s = triangulate(test::gable_house());
  const HausdorffResult r = hausdorff(s, s, 0.2);
  EXPECT_LT(r.symmetric, 1e-9);
  EXPECT_LT(r.mean_a_to_b, 1e-9);
}

TEST(Hausdorff, DifferentTriangulationsOfOneSurface) {
  const PolygonMesh box = test::box({0, 0, 0}, {3, 2, 1});
  PolygonMesh other = box;
  for (Polygon& f : other.faces) std::rotate(f.rings[0].begin(), f.rings[0].begin() + 1, f.rings[0].end());
  const HausdorffResult r = hausdorff(triangulate(box), triangulate(other), 0.05);
  EXPECT_LT(r.symmetric, 1e-9);
}

TEST(Hausdorff, ShiftedBox) {
  PolygonMesh b = test::box({0, 0, 0}, {1, 1, 1});
  const TriangleSoup a = triangulate(b);
  translate(b, {0.1, 0, 0});
  const HausdorffResult r = hausdorff(a, triangulate(b), 0.01);
  EXPECT_NEAR(r.a_to_b, 0.1, 1e-9);  // the x = 0 face is 0.1 from everything of the other box
  EXPECT_NEAR(r.b_to_a, 0.1, 1e-9);
  EXPECT_NEAR(r.symmetric, 0.1, 1e-9);
  // Mean: the two x faces (1/3 of the area) are 0.1 away; of the other four faces only a
  // 0.1-wide strip is off (distance up to 0.1).
  EXPECT_GT(r.mean_a_to_b, 0.1 / 3);
  EXPECT_LT(r.mean_a_to_b, 0.1 / 3 + 0.1 * 0.1);
}

TEST(Hausdorff, OpenSoupAndAsymmetry) {
  // A unit square vs the same square with a 1 m high wall standing on one edge.
  PolygonMesh sq;
  for (Vec3 v : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}}) test::add_vertex(sq, v);
  test::add_face(sq, {0, 1, 2, 3}, "GroundSurface");
  PolygonMesh walled = sq;
  const uint32_t a = test::add_vertex(walled, {0, 0, 1}), b = test::add_vertex(walled, {1, 0, 1});
  test::add_face(walled, {0, 1, b, a}, "WallSurface");
  const HausdorffResult r = hausdorff(triangulate(sq), triangulate(walled), 0.02);
  EXPECT_LT(r.a_to_b, 1e-9);         // the square lies on the walled version
  EXPECT_NEAR(r.b_to_a, 1.0, 1e-9);  // the wall's top edge is 1 m above the square
  EXPECT_NEAR(r.symmetric, 1.0, 1e-9);
  // Means: nothing of the square is off; half of the walled area (the wall) is on average 0.5 m off.
  EXPECT_LT(r.mean_a_to_b, 1e-9);
  EXPECT_NEAR(r.mean_b_to_a, 0.25, 0.01);
  EXPECT_NEAR(r.mean_symmetric, 0.125, 0.005);
}

TEST(Hausdorff, EmptySides) {
  const TriangleSoup s = triangulate(test::box({0, 0, 0}, {1, 1, 1}));
  const HausdorffResult r = hausdorff(s, TriangleSoup{}, 0.1);
  EXPECT_TRUE(std::isinf(r.a_to_b));
  EXPECT_EQ(r.b_to_a, 0);
}

TEST(Hausdorff, GeoreferencedSample) {
  for (const auto& s : test::samples()) {
    if (s.name != "sample13") continue;
    const PolygonMesh m = clean_soup(test::load_off(s.off.string()), 1e-6, nullptr);  // uncentred (~8e5)
    const TriangleSoup t = triangulate(m);
    PolygonMesh moved = m;
    translate(moved, {0, 0, 0.25});
    const HausdorffResult self = hausdorff(t, t, 2.0);
    EXPECT_LT(self.symmetric, 1e-6);
    const HausdorffResult r = hausdorff(t, triangulate(moved), 2.0);
    EXPECT_LE(r.symmetric, 0.25 + 1e-6);
    EXPECT_GT(r.symmetric, 0.2);  // horizontal roofs and floors are exactly 0.25 apart
  }
}

}  // namespace
}  // namespace mc
