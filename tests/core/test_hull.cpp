// Convex hull volume and facets (core/hull.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/hull.hpp"
#include "core/hull_cache.hpp"
#include "tests/core/off_fixture.hpp"

namespace mc {
namespace {

// An octagonal prism: its two caps have eight coplanar points each, which CGAL triangulates in an
// order that follows the input. The hull has 10 facets and the prism's volume.
TEST(Hull, CoplanarCapsAreOneFacetEach) {
  std::vector<Vec3> pts;
  const double pi = std::acos(-1.0);
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < 8; ++i) pts.push_back({std::cos(i * pi / 4), std::sin(i * pi / 4), 3.0 * z});
  const Hull h = convex_hull(pts);
  EXPECT_EQ(h.facets.size(), 10u);
  EXPECT_NEAR(h.volume, 2.0 * std::sqrt(2.0) * 3.0, 1e-12);  // octagon area 2√2 r², height 3
}

// A real 3D BAG building (tests/core/data, CC BY 4.0 3D BAG): roof and wall facets with four or
// more coplanar corners. The volume and facet planes must not depend on the order of the input
// points (CGAL's triangulation of such facets does, and a part's reported hull volume once
// differed in its last bit between two runs with two threads).
TEST(Hull, ResultDoesNotDependOnThePointOrder) {
  const PolygonMesh m =
      test::load_off(std::string(MC_SOURCE_DIR) + "/tests/core/data/3dbag_0503100000018414.off");
  std::vector<Vec3> pts = m.vertices;
  ASSERT_GE(pts.size(), 8u);
  const Hull first = convex_hull(pts);
  ASSERT_GT(first.volume, 0);
  std::mt19937 rng(7);
  for (int round = 0; round < 20; ++round) {
    std::shuffle(pts.begin(), pts.end(), rng);
    const Hull h = convex_hull(pts);
    EXPECT_EQ(h.volume, first.volume);  // bitwise
    ASSERT_EQ(h.facets.size(), first.facets.size());
    for (size_t i = 0; i < h.facets.size(); ++i) {
      EXPECT_EQ(h.facets[i].n.x, first.facets[i].n.x);
      EXPECT_EQ(h.facets[i].n.y, first.facets[i].n.y);
      EXPECT_EQ(h.facets[i].n.z, first.facets[i].n.z);
      EXPECT_EQ(h.facets[i].d, first.facets[i].d);
    }
  }
}

// The building's hull cache (core/hull_cache.hpp): the same point set in another order or with
// repeated points is a hit, and a hit is bitwise the hull computed afresh; another set misses.
// Degenerate on purpose, as building points are, and far from the origin as a city's are: a box
// turned about z (edges along (0.75, 1) and (-1, 0.75): every coordinate exact) sampled on a grid
// over its faces, so that most points are exactly on a facet's plane and many exactly as far from
// a facet as the farthest one. Every such tie is decided by the exact fallback of the hull's
// predicates (core/hull.cpp): the hull is the box, six facets, and a shuffled input gives its
// volume to the last bit.
TEST(Hull, GridPointsOnTheFacesOfAFarTurnedBoxGiveTheBox) {
  const Vec3 origin{85000.25, 446000.5, 3.0}, u{0.75, 1.0, 0.0}, v{-1.0, 0.75, 0.0}, w{0.0, 0.0, 1.0};
  std::vector<Vec3> pts;
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 6; ++j)
      for (int k = 0; k <= 4; ++k) {
        if (i != 0 && i != 10 && j != 0 && j != 6 && k != 0 && k != 4) continue;  // the faces only
        pts.push_back(origin + u * i + v * j + w * k);
      }
  const Hull h = convex_hull(pts);
  EXPECT_EQ(h.facets.size(), 6u);
  EXPECT_NEAR(h.volume, 10 * 6 * 4 * 1.5625, 1e-8);  // |u| = |v| = 1.25
  std::mt19937 rng(3);
  for (int round = 0; round < 5; ++round) {
    std::shuffle(pts.begin(), pts.end(), rng);
    EXPECT_EQ(convex_hull(pts).volume, h.volume);
  }
}

TEST(Hull, CacheHitsAreTheHullOfTheSamePointSet) {
  const PolygonMesh m =
      test::load_off(std::string(MC_SOURCE_DIR) + "/tests/core/data/3dbag_0503100000018414.off");
  std::vector<Vec3> pts = m.vertices;
  HullCache cache;
  const Hull fresh = convex_hull(pts);
  std::mt19937 rng(3);
  for (int round = 0; round < 5; ++round) {
    std::shuffle(pts.begin(), pts.end(), rng);
    std::vector<Vec3> with_repeats = pts;
    with_repeats.insert(with_repeats.end(), pts.begin(), pts.begin() + 5);
    const auto h = cache.get(round % 2 ? with_repeats : pts);
    EXPECT_EQ(h->volume, fresh.volume);  // bitwise
    ASSERT_EQ(h->facets.size(), fresh.facets.size());
    for (size_t i = 0; i < h->facets.size(); ++i) EXPECT_EQ(h->facets[i].d, fresh.facets[i].d);
  }
  EXPECT_EQ(cache.misses(), 1u);
  EXPECT_EQ(cache.hits(), 4u);
  pts.pop_back();  // another set
  const auto other = cache.get(pts);
  EXPECT_EQ(cache.misses(), 2u);
  EXPECT_EQ(other->volume, convex_hull(pts).volume);
}

}  // namespace
}  // namespace mc
