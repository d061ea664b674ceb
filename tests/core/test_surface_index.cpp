// The carving's surface queries (core/surface_index.hpp): does the input surface touch a box,
// and does it reach into a convex cell deeper than a given depth.
#include "core/surface_index.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/plane.hpp"
#include "core/soup.hpp"

namespace mc {
namespace {

// The closed unit cube [0, 1]³ as 12 triangles; `bulge` moves the top face's centre up (a roof
// pushed by fitting noise or a real ridge).
TriangleSoup cube(double bulge = 0) {
  TriangleSoup s;
  s.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0},
                {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                {1, 1, 1}, {0, 1, 1}, {0.5, 0.5, 1 + bulge}};
  s.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7},
                 {2, 7, 6}, {3, 0, 4}, {3, 4, 7}, {4, 5, 8}, {5, 6, 8}, {6, 7, 8}, {7, 4, 8}};
  s.source_face.assign(s.triangles.size(), 0);
  return s;
}

// The box [lo, hi] as outward planes.
std::vector<Plane> box_planes(const Vec3& lo, const Vec3& hi) {
  return {{{-1, 0, 0}, lo.x}, {{1, 0, 0}, -hi.x}, {{0, -1, 0}, lo.y},
          {{0, 1, 0}, -hi.y}, {{0, 0, -1}, lo.z}, {{0, 0, 1}, -hi.z}};
}

TEST(SurfaceIndex, AFaceOnTheCellsBoundaryDoesNotEnterIt) {
  const SurfaceIndex index(cube());
  // The cube's own cell, and the cell of air above its roof: the surface lies on their facets.
  for (const auto& [lo, hi] : {std::pair<Vec3, Vec3>{{0, 0, 0}, {1, 1, 1}}, {{0, 0, 1}, {1, 1, 3}}}) {
    BBox box;
    box.add(lo);
    box.add(hi);
    EXPECT_TRUE(index.touches(box));
    EXPECT_FALSE(index.enters(box_planes(lo, hi), box, 1e-3));
  }
}

TEST(SurfaceIndex, ACellTheSurfaceCrossesIsEntered) {
  const SurfaceIndex index(cube());
  BBox box;
  box.add({0.5, -1, -1});
  box.add({2, 2, 2});  // the face x = 1 cuts through it, 0.5 deep
  EXPECT_TRUE(index.enters(box_planes(box.lo, box.hi), box, 1e-3));
  EXPECT_TRUE(index.enters(box_planes(box.lo, box.hi), box, 0.4));
  EXPECT_FALSE(index.enters(box_planes(box.lo, box.hi), box, 0.6));  // all of it within 0.6 of a facet
}

TEST(SurfaceIndex, FittingNoiseAlongAFacetIsNotEnteringButARidgeIs) {
  // The roof's centre 0.5 mm above the cell's top facet: within a 1 mm depth it only grazes the
  // cell of air above; 5 cm is a ridge that enters it.
  BBox air;
  air.add({0, 0, 1});
  air.add({1, 1, 3});
  EXPECT_FALSE(SurfaceIndex(cube(0.0005)).enters(box_planes(air.lo, air.hi), air, 1e-3));
  EXPECT_TRUE(SurfaceIndex(cube(0.0005)).enters(box_planes(air.lo, air.hi), air, 1e-4));
  EXPECT_TRUE(SurfaceIndex(cube(0.05)).enters(box_planes(air.lo, air.hi), air, 1e-3));
}

TEST(SurfaceIndex, TheTrianglesNearACellAnswerAsTheBoxQueryDoes) {
  // One query of the tree (touching) serves the entering tests of a cell at any depth: the same
  // answers as the queries by box, among them the triangles that really enter.
  const SurfaceIndex index(cube(0.05));
  const std::vector<std::pair<Vec3, Vec3>> cells = {
      {{0, 0, 1}, {1, 1, 3}}, {{0.5, -1, -1}, {2, 2, 2}}, {{0, 0, 0}, {1, 1, 1}}, {{3, 3, 3}, {4, 4, 4}}};
  for (const auto& [lo, hi] : cells) {
    BBox box;
    box.add(lo);
    box.add(hi);
    const std::vector<Plane> outward = box_planes(lo, hi);
    const std::vector<uint32_t> near = index.touching(box);
    for (const double depth : {0.0, 1e-3, 0.04, 0.4, 0.6}) {
      SCOPED_TRACE(testing::Message() << "cell " << lo.x << "," << lo.z << " depth " << depth);
      const std::vector<uint32_t> in = index.entering(outward, near, depth);
      EXPECT_EQ(in, index.entering(outward, box, depth));
      EXPECT_EQ(index.enters(outward, near, depth), index.enters(outward, box, depth));
      EXPECT_EQ(index.enters(outward, near, depth), !in.empty());
      for (const uint32_t t : in) EXPECT_TRUE(std::binary_search(near.begin(), near.end(), t));
    }
  }
  // The ridge's four triangles enter the air above the roof by up to 5 cm; nothing does at 6.
  BBox air;
  air.add({0, 0, 1});
  air.add({1, 1, 3});
  EXPECT_EQ(index.entering(box_planes(air.lo, air.hi), index.touching(air), 1e-3).size(), 4u);
  EXPECT_TRUE(index.entering(box_planes(air.lo, air.hi), index.touching(air), 0.06).empty());
}

TEST(SurfaceIndex, AnEmptySurfaceEntersNothing) {
  const SurfaceIndex index(TriangleSoup{});
  BBox box;
  box.add({0, 0, 0});
  box.add({1, 1, 1});
  EXPECT_FALSE(index.touches(box));
  EXPECT_FALSE(index.enters(box_planes(box.lo, box.hi), box, 0));
}

}  // namespace
}  // namespace mc

namespace mc {
namespace {

TEST(SurfaceIndex, NarrowingAListGivesWhatTheTreeGives) {
  const SurfaceIndex index(cube(0.3));
  BBox all;
  all.add({-1, -1, -1});
  all.add({2, 2, 2});
  const std::vector<uint32_t> every = index.touching(all);
  EXPECT_EQ(every.size(), 14u);
  for (const auto& [lo, hi] : {std::pair<Vec3, Vec3>{{0.2, 0.2, 0.2}, {0.8, 0.8, 0.8}},  // inside: none
                               {{0.9, 0.2, 0.2}, {1.1, 0.4, 0.4}},                       // one wall
                               {{0.4, 0.4, 0.9}, {0.6, 0.6, 1.4}},                       // the apex
                               {{-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}}}) {                 // a corner
    BBox b;
    b.add(lo);
    b.add(hi);
    std::vector<uint32_t> narrowed;
    index.touching(b, every, narrowed);
    EXPECT_EQ(narrowed, index.touching(b));
    EXPECT_EQ(!narrowed.empty(), index.touches(b));
  }
}

TEST(SurfaceIndex, CommonPlaneOfOneFaceButNotOfACorner) {
  const SurfaceIndex index(cube(0.3));
  BBox wall;  // the x = 1 wall's two triangles and nothing else
  wall.add({0.95, 0.3, 0.3});
  wall.add({1.05, 0.7, 0.7});
  Plane pl;
  const std::vector<uint32_t> w = index.touching(wall);
  ASSERT_EQ(w.size(), 2u);
  ASSERT_TRUE(index.common_plane(w, 1e-9, pl));
  EXPECT_NEAR(std::abs(pl.n.x), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(pl.signed_distance({1, 0.5, 0.5})), 0.0, 1e-12);
  BBox corner;
  corner.add({-0.1, -0.1, -0.1});
  corner.add({0.1, 0.1, 0.1});
  EXPECT_FALSE(index.common_plane(index.touching(corner), 1e-3, pl));
  EXPECT_FALSE(index.common_plane({}, 1, pl));
  // The bulged roof is within 0.3 of the top plane: one plane for a generous slab only.
  BBox roof;
  roof.add({0.2, 0.2, 1.05});
  roof.add({0.8, 0.8, 1.35});
  EXPECT_FALSE(index.common_plane(index.touching(roof), 0.01, pl));
}

}  // namespace
}  // namespace mc
