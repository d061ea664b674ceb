// clean_soup, triangulate and centring on synthetic soups and the real samples.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/soup.hpp"
#include "off_fixture.hpp"
#include "synthetic_buildings.hpp"

namespace mc {
namespace {

bool mentions(const std::vector<std::string>& problems, const std::string& word) {
  for (const auto& p : problems)
    if (p.find(word) != std::string::npos) return true;
  return false;
}

double mesh_area(const PolygonMesh& m) {
  double a = 0;
  for (const Polygon& f : m.faces) a += face_geometry(m, f).area;
  return a;
}

TEST(CleanSoup, MergesExplodedBox) {
  const PolygonMesh exploded = test::explode(test::box({0, 0, 0}, {2, 3, 4}));
  ASSERT_EQ(exploded.vertices.size(), 24u);
  std::vector<std::string> problems;
  const PolygonMesh m = clean_soup(exploded, 1e-9, &problems);
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.faces.size(), 6u);
  EXPECT_TRUE(mentions(problems, "duplicate vertices merged"));
  EXPECT_NEAR(mesh_area(m), 2 * (6 + 8 + 12), 1e-9);
}

TEST(CleanSoup, MergesJitteredCopiesWithinTolerance) {
  PolygonMesh exploded = test::explode(test::l_prism());
  test::jitter(exploded, 0.001, 7);  // every copy of a corner moves independently by <= 1 mm
  const PolygonMesh tight = clean_soup(exploded, 1e-6, nullptr);
  EXPECT_GT(tight.vertices.size(), 12u);
  const PolygonMesh loose = clean_soup(exploded, 0.005, nullptr);
  EXPECT_EQ(loose.vertices.size(), 12u);
  EXPECT_EQ(loose.faces.size(), 8u);
}

TEST(CleanSoup, DropsBrokenAndDuplicateFaces) {
  PolygonMesh m = test::box({0, 0, 0}, {1, 1, 1});
  const uint32_t nan = test::add_vertex(m, {std::numeric_limits<double>::quiet_NaN(), 0, 0});
  test::add_vertex(m, {5, 5, 5});  // unused
  const uint32_t c0 = test::add_vertex(m, {0, 0, 2}), c1 = test::add_vertex(m, {1, 0, 2}),
                 c2 = test::add_vertex(m, {2, 0, 2});
  test::add_face(m, {0, 1, nan}, "WallSurface");   // non-finite vertex
  test::add_face(m, {c0, c1, c2}, "WallSurface");  // collinear: zero area
  test::add_face(m, {0, 0, 1}, "WallSurface");     // two distinct points
  test::add_face(m, {0, 1, 99}, "WallSurface");    // index out of range
  Polygon dup = m.faces[0];                        // same ring, rotated and reversed
  std::reverse(dup.rings[0].begin(), dup.rings[0].end());
  std::rotate(dup.rings[0].begin(), dup.rings[0].begin() + 1, dup.rings[0].end());
  m.faces.push_back(dup);
  Polygon repeated = m.faces[1];  // repeated indices, otherwise a new face
  repeated.rings[0] = {repeated.rings[0][0], repeated.rings[0][0], repeated.rings[0][1],
                       repeated.rings[0][2]};
  m.faces.push_back(repeated);

  std::vector<std::string> problems;
  const PolygonMesh c = clean_soup(m, 1e-9, &problems);
  EXPECT_EQ(c.faces.size(), 7u);  // 6 box faces + the repeated-index triangle
  EXPECT_EQ(c.faces.back().rings[0].size(), 3u);
  EXPECT_EQ(c.vertices.size(), 8u);
  for (const Vec3& v : c.vertices) EXPECT_TRUE(is_finite(v));
  EXPECT_TRUE(mentions(problems, "non-finite"));
  EXPECT_TRUE(mentions(problems, "degenerate outer ring"));
  EXPECT_TRUE(mentions(problems, "duplicate faces"));
  EXPECT_TRUE(mentions(problems, "repeated consecutive"));
  EXPECT_TRUE(mentions(problems, "unused vertices"));
  EXPECT_TRUE(mentions(problems, "bad index"));
}

TEST(CleanSoup, DropsDegenerateHoleKeepsFace) {
  PolygonMesh m;
  for (Vec3 v : {Vec3{0, 0, 0}, Vec3{4, 0, 0}, Vec3{4, 4, 0}, Vec3{0, 4, 0}, Vec3{1, 1, 0}, Vec3{2, 2, 0},
                 Vec3{3, 3, 0}})
    test::add_vertex(m, v);
  Polygon f;
  f.rings = {{0, 1, 2, 3}, {4, 5, 6}};  // the hole is collinear
  m.faces.push_back(f);
  std::vector<std::string> problems;
  const PolygonMesh c = clean_soup(m, 0, &problems);
  ASSERT_EQ(c.faces.size(), 1u);
  EXPECT_EQ(c.faces[0].rings.size(), 1u);
  EXPECT_TRUE(mentions(problems, "hole"));
}

TEST(Triangulate, BoxKeepsAreaOrientationAndSource) {
  const PolygonMesh m = test::l_prism();
  const TriangleSoup s = triangulate(m);
  EXPECT_EQ(s.triangles.size(), 6 * 2 + 2 * 4u);  // 6 quads, 2 hexagons
  ASSERT_EQ(s.source_face.size(), s.triangles.size());
  EXPECT_NEAR(test::soup_area(s), mesh_area(m), 1e-9);
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tri = s.triangles[t];
    const Vec3 n = cross(s.vertices[tri[1]] - s.vertices[tri[0]], s.vertices[tri[2]] - s.vertices[tri[0]]);
    EXPECT_GT(dot(n, face_geometry(m, m.faces[s.source_face[t]]).normal), 0) << "triangle " << t;
  }
}

TEST(Triangulate, PolygonWithHoleAndNonConvex) {
  PolygonMesh m;
  for (Vec3 v : {Vec3{0, 0, 0}, Vec3{10, 0, 0}, Vec3{10, 0, 10}, Vec3{0, 0, 10},  // wall in y = 0
                 Vec3{2, 0, 2}, Vec3{4, 0, 2}, Vec3{4, 0, 4}, Vec3{2, 0, 4}})
    test::add_vertex(m, v);
  Polygon wall;
  wall.rings = {{0, 1, 2, 3}, {4, 7, 6, 5}};
  m.faces.push_back(wall);
  // Non-convex U shape in z = 0.
  const uint32_t b = static_cast<uint32_t>(m.vertices.size());
  for (Vec3 v : {Vec3{0, 0, 0}, Vec3{6, 0, 0}, Vec3{6, 6, 0}, Vec3{4, 6, 0}, Vec3{4, 2, 0}, Vec3{2, 2, 0},
                 Vec3{2, 6, 0}, Vec3{0, 6, 0}})
    test::add_vertex(m, v);
  test::add_face(m, {b, b + 1, b + 2, b + 3, b + 4, b + 5, b + 6, b + 7}, "GroundSurface");
  const TriangleSoup s = triangulate(m);
  double wall_area = 0, u_area = 0;
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tri = s.triangles[t];
    const double a =
        0.5 * norm(cross(s.vertices[tri[1]] - s.vertices[tri[0]], s.vertices[tri[2]] - s.vertices[tri[0]]));
    (s.source_face[t] == 0 ? wall_area : u_area) += a;
  }
  EXPECT_NEAR(wall_area, 96, 1e-9);
  EXPECT_NEAR(u_area, 36 - 8, 1e-9);
}

TEST(Triangulate, NonPlanarAndSelfIntersectingRings) {
  PolygonMesh m;
  for (Vec3 v : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0.3}, Vec3{0, 1, 0}}) test::add_vertex(m, v);
  test::add_face(m, {0, 1, 2, 3}, "RoofSurface");  // warped quad
  const uint32_t b = static_cast<uint32_t>(m.vertices.size());
  for (Vec3 v : {Vec3{0, 0, 5}, Vec3{2, 2, 5}, Vec3{2, 0, 5}, Vec3{0, 2, 5}}) test::add_vertex(m, v);
  test::add_face(m, {b, b + 1, b + 2, b + 3}, "RoofSurface");  // bow tie
  const TriangleSoup s = triangulate(m);
  size_t warped = 0, bowtie = 0;
  for (uint32_t f : s.source_face) (f == 0 ? warped : bowtie)++;
  EXPECT_EQ(warped, 2u);
  EXPECT_EQ(bowtie, 2u);  // the two lobes; their shared point is new
  EXPECT_EQ(s.vertices.size(), m.vertices.size() + 1);
  EXPECT_NEAR(s.vertices.back().x, 1, 1e-9);
  EXPECT_NEAR(s.vertices.back().y, 1, 1e-9);
  EXPECT_NEAR(s.vertices.back().z, 5, 1e-9);
}

TEST(Centre, BboxCenterAndTranslate) {
  PolygonMesh m = test::box({1, 2, 3}, {5, 10, 4});
  test::add_vertex(m, {100, 100, 100});  // unused vertices do not count
  const Vec3 c = bbox_center(m);
  EXPECT_EQ(c, (Vec3{3, 6, 3.5}));
  translate(m, -c);
  EXPECT_EQ(bbox_center(m), (Vec3{0, 0, 0}));
}

TEST(Samples, CleanAndTriangulateEverySample) {
  const auto all = test::samples();
  ASSERT_GE(all.size(), 16u) << "sample data missing at " << test::samples_dir();
  for (const auto& s : all) {
    const PolygonMesh raw = test::load_off(s.off.string());
    std::vector<std::string> problems;
    const PolygonMesh m = clean_soup(raw, 1e-6, &problems);
    ASSERT_FALSE(m.faces.empty()) << s.name;
    EXPECT_LE(m.vertices.size(), raw.vertices.size()) << s.name;
    const TriangleSoup t = triangulate(m);
    // Triangulation must cover each face: total area matches the polygon areas (non-planar
    // faces project, so allow 1%).
    EXPECT_NEAR(test::soup_area(t), mesh_area(m), 0.01 * mesh_area(m)) << s.name;
    std::vector<bool> covered(m.faces.size());
    for (uint32_t f : t.source_face) covered[f] = true;
    EXPECT_EQ(std::count(covered.begin(), covered.end(), false), 0) << s.name;
  }
}

}  // namespace
}  // namespace mc
