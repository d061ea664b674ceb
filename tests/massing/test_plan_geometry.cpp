// Plan geometry of the massing analytics (massing/plan_geometry.hpp): a footprint's width and
// length, areas with holes, unions of touching polygons.
#include <gtest/gtest.h>

#include <cmath>

#include "massing/plan_geometry.hpp"

namespace mc::massing {
namespace {

mc::io::Ring2 rectangle(double w, double l, double angle_deg, double x0, double y0) {
  const double a = angle_deg * M_PI / 180, c = std::cos(a), s = std::sin(a);
  mc::io::Ring2 r;
  for (const auto& [u, v] : std::vector<std::pair<double, double>>{{0, 0}, {l, 0}, {l, w}, {0, w}})
    r.push_back({x0 + c * u - s * v, y0 + s * u + c * v});
  return r;
}

TEST(PlanGeometry, WidthAndLengthOfARotatedSlabFarFromTheOrigin) {
  const PlanExtent e = plan_extent(rectangle(3.6, 13, 27, 85000, 446000));
  EXPECT_NEAR(e.width, 3.6, 1e-6);
  EXPECT_NEAR(e.length, 13, 1e-6);
}

TEST(PlanGeometry, AreaSubtractsHoles) {
  mc::io::Polygon2 p{rectangle(10, 10, 0, 0, 0), rectangle(2, 2, 0, 4, 4)};
  std::reverse(p[1].begin(), p[1].end());
  EXPECT_NEAR(polygon_area(p), 96, 1e-9);
}

TEST(PlanGeometry, UnionOfTwoTouchingSquaresIsOneRectangle) {
  bool ok = false;
  const mc::io::MultiPolygon2 u =
      union_of({mc::io::Polygon2{rectangle(4, 4, 0, 0, 0)}, mc::io::Polygon2{rectangle(4, 4, 0, 4, 0)}}, ok);
  ASSERT_TRUE(ok);
  ASSERT_EQ(u.size(), 1u);
  EXPECT_NEAR(multipolygon_area(u), 32, 1e-9);
  const PlanExtent e = plan_extent(outer_hull(u));
  EXPECT_NEAR(e.width, 4, 1e-9);
  EXPECT_NEAR(e.length, 8, 1e-9);
}

}  // namespace
}  // namespace mc::massing
