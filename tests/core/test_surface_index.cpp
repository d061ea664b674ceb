// The carving's surface queries (core/surface_index.hpp): does the input surface touch a box,
// and does it reach into a convex cell deeper than a given depth.
#include "core/surface_index.hpp"

#include <gtest/gtest.h>

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
