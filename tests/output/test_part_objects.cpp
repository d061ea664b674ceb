// Parts as CityJSON Solids on the output grid (output/part_objects.hpp) and the closed-shell check
// (output/solid_check.hpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/core/labelled_box.hpp"
#include "output/part_objects.hpp"
#include "output/solid_check.hpp"

namespace {

using namespace mc;
using namespace mc::output;

TEST(SolidCheck, ClosedBoxPassesDefectsAreNamed) {
  Shell cube = {{{0, 2, 3, 1}}, {{4, 5, 7, 6}}, {{0, 1, 5, 4}},
                {{2, 6, 7, 3}}, {{0, 4, 6, 2}}, {{1, 3, 7, 5}}};
  EXPECT_EQ(closed_shell_defect(cube), "");
  Shell open = cube;
  open.pop_back();
  EXPECT_NE(closed_shell_defect(open).find("boundary"), std::string::npos);
  Shell flipped = cube;
  std::reverse(flipped[0][0].begin(), flipped[0][0].end());
  EXPECT_NE(closed_shell_defect(flipped).find("same direction"), std::string::npos);
  // Two cubes sharing only vertex 7 (the second one's corner 0): every edge is fine, the vertex not.
  Shell two = cube;
  for (auto face : cube) {
    for (auto& v : face[0]) v = v == 0 ? 7 : v + 10;
    two.push_back(face);
  }
  EXPECT_NE(closed_shell_defect(two).find("two separate fans"), std::string::npos);
  // Two disjoint cubes: closed and manifold everywhere, but two shells.
  Shell apart = cube;
  for (auto face : cube) {
    for (auto& v : face[0]) v += 20;
    apart.push_back(face);
  }
  EXPECT_NE(closed_shell_defect(apart).find("more than one connected shell"), std::string::npos);
}

TEST(EncodeSolid, SnapsToTheTransformGridDedupesAndKeepsLabels) {
  std::vector<Vec3> out{{1, 2, 3}};  // an existing feature vertex stays first
  mc::io::Transform t;
  t.present = true;
  t.scale = {0.001, 0.001, 0.001};
  t.translate = {85000, 446000, 0};
  VertexPool pool(out, t);
  PolygonMesh m = mc::test::labelled_box({85000.00012, 446000, 0}, {10, 20, 6});
  const EncodedSolid a = encode_solid(m, "2.2", "2.0", pool);
  EXPECT_EQ(closed_shell_defect(a.shell), "");
  EXPECT_EQ(out.size(), 9u);
  EXPECT_NEAR(out[1].x, 85000.0, 1e-9);  // snapped to the mm grid
  EXPECT_EQ(a.geometry["lod"], "2.2");
  EXPECT_EQ(a.geometry["semantics"]["surfaces"].size(), 4u);
  EXPECT_EQ(a.geometry["semantics"]["values"][0].size(), 6u);
  // A second part sharing a face reuses the vertices on the grid.
  const EncodedSolid b =
      encode_solid(mc::test::labelled_box({85010, 446000, 0}, {10, 20, 6}), "2.2", "2.0", pool);
  EXPECT_EQ(out.size(), 13u);
  // A face thinner than the grid collapses and is dropped, counted.
  PolygonMesh thin = mc::test::labelled_box({85000, 446000, 0}, {10, 0.0001, 6});
  const EncodedSolid c = encode_solid(thin, "2", "1.0", pool);
  EXPECT_GT(c.dropped_faces, 0u);
  EXPECT_TRUE(c.geometry["lod"].is_number());
}

}  // namespace
