// Hausdorff distance between triangle soups.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "core/hausdorff.hpp"
#include "off_fixture.hpp"
#include "synthetic_buildings.hpp"

namespace mc {
namespace {

// Brute-force distance from p to the nearest triangle of s (Ericson's closest point, written
// out independently of the library's: by projection onto the plane, else onto the edges).
double brute_distance(const Vec3& p, const TriangleSoup& s) {
  double best = std::numeric_limits<double>::infinity();
  auto seg = [](const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
    return norm(p - (a + ab * t));
  };
  for (const auto& t : s.triangles) {
    const Vec3 &a = s.vertices[t[0]], &b = s.vertices[t[1]], &c = s.vertices[t[2]];
    const Vec3 n = normalized(cross(b - a, c - a));
    const Vec3 q = p - n * dot(p - a, n);
    const bool inside = dot(cross(b - a, q - a), n) >= 0 && dot(cross(c - b, q - b), n) >= 0 &&
                        dot(cross(a - c, q - c), n) >= 0;
    best = std::min(best,
                    inside ? std::abs(dot(p - a, n)) : std::min({seg(p, a, b), seg(p, b, c), seg(p, c, a)}));
  }
  return best;
}

// The closest-point queries find the nearest of many triangles exactly, far from the origin too
// (Embree's boxes are in floats; the distances must not be): a triangle smaller than the step is
// sampled at its three corners only, so the one-sided maximum and mean are known exactly.
TEST(Hausdorff, NearestOfManyTrianglesIsExact) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 100), small(-0.001, 0.001);
  const Vec3 far{85000, 446000, 0};
  TriangleSoup many;
  for (int i = 0; i < 400; ++i) {
    const Vec3 c = far + Vec3{u(rng), u(rng), u(rng) / 4};
    for (int k = 0; k < 3; ++k) many.vertices.push_back(c + Vec3{u(rng) / 20, u(rng) / 20, u(rng) / 20});
    many.triangles.push_back({3u * i, 3u * i + 1, 3u * i + 2});
  }
  // Around each query corner, 30 small axis-aligned squares facing it (their boxes are as near
  // as they are) at distances 10 m + j micrometres, in scrambled order and axis directions: the
  // nearest differs from the others by less than Embree's float rounding of the coordinates.
  for (int trial = 0; trial < 20; ++trial) {
    TriangleSoup tiny;
    const Vec3 c = far + Vec3{u(rng), u(rng), u(rng) / 4};
    tiny.vertices = {c, c + Vec3{1e-4, 0, 0}, c + Vec3{0, 1e-4, 0}};
    tiny.triangles = {{0, 1, 2}};
    TriangleSoup soup = many;
    for (int j = 0; j < 30; ++j) {
      const int k = (j * 17 + trial) % 30, axis = k % 3;
      const double sign = (k / 3) % 2 ? 1.0 : -1.0;
      Vec3 e[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
      const Vec3 q = c + e[axis] * (sign * (10 + 1e-6 * j));
      const Vec3 a = e[(axis + 1) % 3] * 0.05, b = e[(axis + 2) % 3] * 0.05;
      const uint32_t v = static_cast<uint32_t>(soup.vertices.size());
      for (const Vec3& w : {q - a - b, q + a - b, q + a + b, q - a + b}) soup.vertices.push_back(w);
      soup.triangles.push_back({v, v + 1, v + 2});
      soup.triangles.push_back({v, v + 2, v + 3});
    }
    const HausdorffResult r = hausdorff(tiny, soup, 1.0);
    double mx = 0, mean = 0;
    for (const Vec3& v : tiny.vertices) {
      const double d = brute_distance(v, soup);
      mx = std::max(mx, d);
      mean += d / 3;
    }
    EXPECT_NEAR(r.a_to_b, mx, 1e-9);
    EXPECT_NEAR(r.mean_a_to_b, mean, 1e-9);
  }
}

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

// Without the means only the triangles that can hold the maximum are sampled: the maxima are the
// full lattice's bit for bit, on every sample against its noisy, shifted and rotated copy (some
// triangles far, some on the other surface, the maximum anywhere).
TEST(Hausdorff, MaximaWithoutMeansAreTheFullLattices) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  int compared = 0;
  for (const auto& s : test::samples()) {
    const PolygonMesh m = clean_soup(test::load_off(s.off.string()), 1e-6, nullptr);
    const TriangleSoup a = triangulate(m);
    TriangleSoup b = a;
    const double c = std::cos(0.01), sn = std::sin(0.01);
    for (Vec3& v : b.vertices)
      v = Vec3{c * v.x - sn * v.y, sn * v.x + c * v.y, v.z} + Vec3{0, 0, jitter(rng)};
    for (const double step : {0.0, 0.5}) {
      const HausdorffResult full = hausdorff(a, b, step), maxima = hausdorff(a, b, step, false);
      EXPECT_EQ(full.a_to_b, maxima.a_to_b) << s.name;
      EXPECT_EQ(full.b_to_a, maxima.b_to_a) << s.name;
      EXPECT_EQ(full.symmetric, maxima.symmetric) << s.name;
      EXPECT_EQ(maxima.mean_a_to_b, 0);
      ++compared;
    }
  }
  EXPECT_GE(compared, 20);
  const TriangleSoup sq = triangulate(test::box({0, 0, 0}, {1, 1, 1}));
  PolygonMesh shifted = test::box({0, 0, 0}, {1, 1, 1});
  translate(shifted, {0.1, 0, 0});
  const HausdorffResult r = hausdorff(sq, triangulate(shifted), 0.01, false);
  EXPECT_NEAR(r.symmetric, 0.1, 1e-9);
}

}  // namespace
}  // namespace mc
