// check_solid and common_volume on hand-made shells: one for every error code they report.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/solid_validation.hpp"

namespace mc {
namespace {

using Rings = std::vector<std::vector<uint32_t>>;

PolygonMesh mesh(std::vector<Vec3> v, const std::vector<Rings>& faces) {
  PolygonMesh m;
  m.vertices = std::move(v);
  for (const auto& f : faces) m.faces.push_back({f, -1});
  return m;
}

// Axis-aligned box, faces counter-clockwise seen from outside.
PolygonMesh box(Vec3 lo, Vec3 hi) {
  return mesh(
      {{lo.x, lo.y, lo.z},
       {hi.x, lo.y, lo.z},
       {hi.x, hi.y, lo.z},
       {lo.x, hi.y, lo.z},
       {lo.x, lo.y, hi.z},
       {hi.x, lo.y, hi.z},
       {hi.x, hi.y, hi.z},
       {lo.x, hi.y, hi.z}},
      {{{0, 3, 2, 1}}, {{4, 5, 6, 7}}, {{0, 1, 5, 4}}, {{2, 3, 7, 6}}, {{0, 4, 7, 3}}, {{1, 2, 6, 5}}});
}

PolygonMesh unit_cube() { return box({0, 0, 0}, {1, 1, 1}); }

// Two shells as one mesh (vertices are merged by coordinates in check_solid).
PolygonMesh merged(const PolygonMesh& a, const PolygonMesh& b) {
  PolygonMesh m = a;
  const uint32_t base = static_cast<uint32_t>(a.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Polygon f : b.faces) {
    for (auto& r : f.rings)
      for (auto& v : r) v += base;
    m.faces.push_back(f);
  }
  return m;
}

std::vector<int> codes(const SolidCheck& c) {
  std::vector<int> out;
  for (const auto& e : c.errors) out.push_back(e.code);
  return out;
}

bool has(const SolidCheck& c, int code) {
  const auto v = codes(c);
  return std::find(v.begin(), v.end(), code) != v.end();
}

std::string describe(const SolidCheck& c) {
  std::string s;
  for (const auto& e : c.errors) s += std::to_string(e.code) + " " + e.name + ": " + e.message + "\n";
  return s;
}

TEST(SolidValidation, UnitCubeIsValid) {
  const SolidCheck c = check_solid(unit_cube());
  EXPECT_TRUE(c.valid()) << describe(c);
  EXPECT_TRUE(c.closed_manifold);
  EXPECT_NEAR(c.volume, 1.0, 1e-12);
  EXPECT_NEAR(c.area, 6.0, 1e-12);
  EXPECT_NEAR(c.hull_volume, 1.0, 1e-9);
  EXPECT_NEAR(c.convexity, 1.0, 1e-9);
  EXPECT_EQ(c.shell.triangles.size(), 12u);
}

TEST(SolidValidation, CityCoordinatesKeepTheirPrecision) {
  const SolidCheck c = check_solid(box({85012.125, 446210.5, -2.0}, {85022.125, 446216.5, 7.5}));
  EXPECT_TRUE(c.valid()) << describe(c);
  EXPECT_NEAR(c.volume, 10 * 6 * 9.5, 1e-6);
}

TEST(SolidValidation, FrameWithAHoleThroughIt) {
  // A unit square frame around a 0.5 x 0.5 hole: the top and bottom faces have inner rings.
  std::vector<Vec3> v;
  for (double z : {0.0, 1.0}) {
    for (auto [x, y] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}) v.push_back({x, y, z});
    for (auto [x, y] : {std::pair{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}})
      v.push_back({x, y, z});
  }
  // Bottom: outer 0-3, inner 4-7; top: outer 8-11, inner 12-15.
  const SolidCheck c = check_solid(mesh(v, {{{0, 3, 2, 1}, {4, 5, 6, 7}},
                                            {{8, 9, 10, 11}, {12, 15, 14, 13}},
                                            {{0, 1, 9, 8}},
                                            {{2, 3, 11, 10}},
                                            {{0, 8, 11, 3}},
                                            {{1, 2, 10, 9}},
                                            {{4, 7, 15, 12}},
                                            {{5, 13, 14, 6}},
                                            {{5, 4, 12, 13}},
                                            {{7, 6, 14, 15}}}));
  EXPECT_TRUE(c.valid()) << describe(c);
  EXPECT_NEAR(c.volume, 0.75, 1e-12);
  EXPECT_NEAR(c.convexity, 0.75, 1e-9);
}

TEST(SolidValidation, MissingFaceIsNotClosed) {
  PolygonMesh m = unit_cube();
  m.faces.pop_back();
  const SolidCheck c = check_solid(m);
  EXPECT_TRUE(has(c, 302)) << describe(c);
  EXPECT_FALSE(c.closed_manifold);
  EXPECT_EQ(c.errors[0].name, "SHELL_NOT_CLOSED");
}

TEST(SolidValidation, InwardFacesAreWronglyOriented) {
  PolygonMesh m = unit_cube();
  for (auto& f : m.faces) std::reverse(f.rings[0].begin(), f.rings[0].end());
  const SolidCheck c = check_solid(m);
  EXPECT_EQ(codes(c), std::vector<int>{307}) << describe(c);
  EXPECT_NEAR(c.volume, -1.0, 1e-12);
  EXPECT_FALSE(c.closed_manifold);
}

TEST(SolidValidation, OneFlippedFace) {
  PolygonMesh m = unit_cube();
  std::reverse(m.faces[1].rings[0].begin(), m.faces[1].rings[0].end());
  const SolidCheck c = check_solid(m);
  EXPECT_EQ(codes(c), std::vector<int>{304}) << describe(c);
}

TEST(SolidValidation, ShellThroughItself) {
  // The cube as triangles, one corner pushed through the opposite corner: closed, 2-manifold,
  // every face planar, but its faces cross.
  const PolygonMesh q = unit_cube();
  PolygonMesh m;
  m.vertices = q.vertices;
  for (const auto& f : q.faces) {
    const auto& r = f.rings[0];
    m.faces.push_back({{{r[0], r[1], r[2]}}, -1});
    m.faces.push_back({{{r[0], r[2], r[3]}}, -1});
  }
  m.vertices[6] = {-0.5, -0.4, -0.3};
  const SolidCheck c = check_solid(m);
  EXPECT_TRUE(has(c, 306)) << describe(c);
  EXPECT_FALSE(c.closed_manifold);
}

TEST(SolidValidation, BowTieRing) {
  PolygonMesh m = unit_cube();
  m.faces[1].rings[0] = {4, 6, 5, 7};  // the top face's diagonals as edges
  const SolidCheck c = check_solid(m);
  EXPECT_TRUE(has(c, 104)) << describe(c);
}

TEST(SolidValidation, NonPlanarQuadBeyondTheToleranceOnly) {
  PolygonMesh m = unit_cube();
  m.vertices[6].z += 0.01;  // only the top face bends (the move is in the planes of the sides)
  SolidCheck c = check_solid(m);
  EXPECT_EQ(codes(c), std::vector<int>{203}) << describe(c);
  EXPECT_NE(c.errors[0].message.find("face 1: a point lies 0.0025 m"), std::string::npos)
      << c.errors[0].message;
  EXPECT_TRUE(c.closed_manifold);  // the shell checks still ran
  m.vertices[6].z = 1.0008;        // 0.2 mm off the plane
  c = check_solid(m);
  EXPECT_TRUE(c.valid()) << describe(c);
  EXPECT_FALSE(check_solid(m, {1e-6, 1e-4}).valid());
}

TEST(SolidValidation, CubesSharingAnEdgeOrAVertexAreNotManifold) {
  const SolidCheck edge = check_solid(merged(unit_cube(), box({1, 1, 0}, {2, 2, 1})));
  EXPECT_TRUE(has(edge, 303)) << describe(edge);
  EXPECT_NE(edge.errors[0].message.find("shared by 4 faces"), std::string::npos) << describe(edge);
  const SolidCheck vertex = check_solid(merged(unit_cube(), box({1, 1, 1}, {2, 2, 2})));
  EXPECT_TRUE(has(vertex, 303)) << describe(vertex);
  EXPECT_NE(vertex.errors[0].message.find("separate fans"), std::string::npos) << describe(vertex);
  const SolidCheck apart = check_solid(merged(unit_cube(), box({3, 0, 0}, {4, 1, 1})));
  EXPECT_EQ(codes(apart), std::vector<int>{305}) << describe(apart);
}

TEST(SolidValidation, DuplicateConsecutivePointsAndTooFewPoints) {
  PolygonMesh m = unit_cube();
  m.faces[0].rings[0] = {0, 3, 3, 2, 1};
  EXPECT_EQ(codes(check_solid(m)), std::vector<int>{102});
  m.vertices.push_back({0, 1, 0.0000001});  // a copy of vertex 3 within the snap tolerance
  m.faces[0].rings[0] = {0, 3, 8, 2, 1};
  EXPECT_EQ(codes(check_solid(m)), std::vector<int>{102});
  m.faces[0].rings[0] = {0, 3};
  const SolidCheck c = check_solid(m);
  EXPECT_TRUE(has(c, 101)) << describe(c);
  EXPECT_TRUE(has(c, 302)) << describe(c);  // the face is gone: a hole in the shell
}

TEST(SolidValidation, CommonVolumeTouchingOverlappingIdentical) {
  const SolidCheck a = check_solid(unit_cube());
  const SolidCheck touching = check_solid(box({1, 0, 0}, {2, 1, 1}));
  const SolidCheck half = check_solid(box({0.5, 0, 0}, {1.5, 1, 1}));
  const SolidCheck inside = check_solid(box({0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}));
  ASSERT_TRUE(a.valid() && touching.valid() && half.valid() && inside.valid());
  EXPECT_NEAR(common_volume(a.shell, touching.shell).value().volume, 0.0, 1e-12);
  EXPECT_NEAR(common_volume(a.shell, half.shell).value().volume, 0.5, 1e-9);
  EXPECT_NEAR(common_volume(a.shell, half.shell).value().area, 4.0, 1e-9);
  EXPECT_NEAR(common_volume(a.shell, a.shell).value().volume, 1.0, 1e-9);
  EXPECT_NEAR(common_volume(a.shell, inside.shell).value().volume, 0.125, 1e-9);
  // The fallback agrees, shared faces included.
  EXPECT_NEAR(common_volume_by_faces(a.shell, touching.shell).value().volume, 0.0, 1e-12);
  EXPECT_NEAR(common_volume_by_faces(a.shell, half.shell).value().volume, 0.5, 1e-9);
  EXPECT_NEAR(common_volume_by_faces(a.shell, half.shell).value().area, 4.0, 1e-9);
  EXPECT_NEAR(common_volume_by_faces(a.shell, a.shell).value().volume, 1.0, 1e-9);
  EXPECT_NEAR(common_volume_by_faces(a.shell, inside.shell).value().volume, 0.125, 1e-9);
  EXPECT_NEAR(common_volume_by_faces(inside.shell, a.shell).value().volume, 0.125, 1e-9);
  // A shell that is not a 2-manifold cannot be corefined: no number rather than a guess.
  EXPECT_FALSE(common_volume(
      a.shell, check_solid(merged(box({0, 0, 0}, {1, 1, 1}), box({1, 1, 0}, {2, 2, 1}))).shell));
}

}  // namespace
}  // namespace mc
