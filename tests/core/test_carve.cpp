// The carving's vote by regions (core/carve.hpp `region_vote`, docs/design.md "Regions, not
// points"): the same count as classifying every point where the oracle is constant off the
// surface, far fewer queries, every point classified where it is not, exact beside one plane; a
// vote allowed to stop stops once both labels are settled, with lower bounds of both counts.
#include "core/carve.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "buildings.hpp"
#include "core/soup.hpp"
#include "core/surface_index.hpp"

namespace mc {
namespace {

// The L prism of test::l_building (x, y in the L of [0,12]², 0 < z < 6).
bool in_l(const Vec3& p) {
  const bool plan = p.x > 0 && p.x < 12 && p.y > 0 && p.y < 12 && !(p.x > 5 && p.y > 5);
  return plan && p.z > 0 && p.z < 6;
}

std::vector<Vec3> random_points(size_t n, const Vec3& lo, const Vec3& hi, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> pts(n);
  for (Vec3& p : pts)
    p = {lo.x + u(rng) * (hi.x - lo.x), lo.y + u(rng) * (hi.y - lo.y), lo.z + u(rng) * (hi.z - lo.z)};
  return pts;
}

BBox box_of(const std::vector<Vec3>& pts) {
  BBox b;
  for (const Vec3& p : pts) b.add(p);
  return b;
}

// A classifier from a point predicate; counts its queries.
struct Exact {
  bool (*inside)(const Vec3&);
  size_t queries = 0;
  PointClassifier fn() {
    return [this](const std::vector<Vec3>& pts, const std::vector<uint64_t>&, std::vector<uint8_t>& out) {
      out.resize(pts.size());
      for (size_t i = 0; i < pts.size(); ++i) out[i] = inside(pts[i]);
      queries += pts.size();
    };
  }
};

size_t count_inside(const std::vector<Vec3>& pts, bool (*inside)(const Vec3&)) {
  size_t n = 0;
  for (const Vec3& p : pts) n += inside(p);
  return n;
}

TEST(RegionVote, CountsAsEveryPointWouldWithAFractionOfTheQueries) {
  const TriangleSoup soup = triangulate(test::l_building());
  const SurfaceIndex index(soup);
  const auto pts = random_points(20000, {-1, -1, -1}, {13, 13, 7}, 1);
  const BBox box = box_of(pts);
  Exact oracle{in_l};
  size_t classified = 0;
  const RegionCount count =
      region_vote(pts, 0, 9, index, index.touching(box), 0.01, BBox{}, oracle.fn(), classified);
  EXPECT_TRUE(count.complete);
  EXPECT_EQ(count.in, count_inside(pts, in_l));
  EXPECT_EQ(count.in + count.out, pts.size());
  EXPECT_EQ(classified, oracle.queries);
  EXPECT_LT(classified, pts.size() / 4);
}

TEST(RegionVote, ADisagreeingRegionHasEveryPointClassified) {
  // An oracle that is not constant off the surface (as parity is beside a gap in an open input):
  // inside for two ids in three, wherever the point is. The vote must count what it says.
  const TriangleSoup soup = triangulate(test::l_building());
  const SurfaceIndex index(soup);
  const auto pts = random_points(5000, {-1, -1, -1}, {13, 13, 7}, 2);
  size_t queries = 0, truth = 0;
  for (size_t i = 0; i < pts.size(); ++i) truth += (i % 3) != 0;
  const PointClassifier noisy = [&](const std::vector<Vec3>& q, const std::vector<uint64_t>& ids,
                                    std::vector<uint8_t>& out) {
    out.resize(q.size());
    for (size_t i = 0; i < q.size(); ++i) out[i] = (ids[i] % 3) != 0;
    queries += q.size();
  };
  size_t classified = 0;
  const size_t in =
      region_vote(pts, 0, 9, index, index.touching(box_of(pts)), 0.01, BBox{}, noisy, classified).in;
  // A region whose 9 points happen to agree is labelled whole (0.7 % of 9-point draws): close
  // to, not exactly, the point-by-point count.
  EXPECT_NEAR(double(in), double(truth), 0.02 * pts.size());
  EXPECT_GT(classified, pts.size() * 9 / 10);
  EXPECT_EQ(classified, queries);
}

bool below_3(const Vec3& p) { return p.z < 3; }

TEST(RegionVote, PointsOnEitherSideOfOnePlaneAreTwoRegions) {
  // One horizontal sheet across the whole box: every box of points is touched, yet the points
  // beyond the slab on each side are uniform.
  TriangleSoup sheet;
  sheet.vertices = {{-5, -5, 3}, {20, -5, 3}, {20, 20, 3}, {-5, 20, 3}};
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
  sheet.source_face = {0, 0};
  const SurfaceIndex index(sheet);
  const auto pts = random_points(20000, {0, 0, 0}, {10, 10, 6}, 3);
  Exact oracle{below_3};
  size_t classified = 0;
  const size_t in =
      region_vote(pts, 0, 9, index, index.touching(box_of(pts)), 0.01, BBox{}, oracle.fn(), classified).in;
  EXPECT_EQ(in, count_inside(pts, below_3));
  EXPECT_LT(classified, 200u);  // the two sides' points and the few within 1 cm of the sheet
}

bool in_unit_box(const Vec3& p) { return p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1 && p.z > 0 && p.z < 1; }

TEST(RegionVote, ABoxAcrossTheOraclesBoxIsNotUniform) {
  // No surface at all, but beyond the oracle's box everything is outside: a region reaching out
  // of it is split until its boxes lie on one side.
  TriangleSoup none;
  const SurfaceIndex index(none);
  BBox oracle_box;
  oracle_box.add({0, 0, 0});
  oracle_box.add({1, 1, 1});
  const auto pts = random_points(20000, {-1, -1, -1}, {2, 2, 2}, 4);
  Exact oracle{in_unit_box};
  size_t classified = 0;
  const size_t in = region_vote(pts, 0, 9, index, {}, 0.01, oracle_box, oracle.fn(), classified).in;
  EXPECT_EQ(in, count_inside(pts, in_unit_box));
  EXPECT_LT(classified, pts.size() / 2);
}

TEST(RegionVote, AMixedCellStopsOnceBothLabelsAreSettled) {
  // A cell that holds the L's inside and its air: once the untouched regions settle 500 points
  // of each label the vote stops, with lower bounds of both counts, long before the points near
  // the surface are classified.
  const TriangleSoup soup = triangulate(test::l_building());
  const SurfaceIndex index(soup);
  const auto pts = random_points(20000, {-1, -1, -1}, {13, 13, 7}, 6);
  const size_t truth = count_inside(pts, in_l);
  Exact full_oracle{in_l}, oracle{in_l};
  size_t full_classified = 0, classified = 0;
  const RegionCount full = region_vote(pts, 0, 9, index, index.touching(box_of(pts)), 0.01, BBox{},
                                       full_oracle.fn(), full_classified);
  const RegionCount stopped =
      region_vote(pts, 0, 9, index, index.touching(box_of(pts)), 0.01, BBox{}, oracle.fn(), classified, 500);
  EXPECT_TRUE(full.complete);
  EXPECT_FALSE(stopped.complete);
  EXPECT_GE(stopped.in, 500u);
  EXPECT_GE(stopped.out, 500u);
  EXPECT_LE(stopped.in, truth);
  EXPECT_LE(stopped.out, pts.size() - truth);
  EXPECT_EQ(classified, oracle.queries);
  EXPECT_LT(classified * 10, full_classified);
}

TEST(RegionVote, AVoteThatCannotSettleBothLabelsIsComplete) {
  // Asking for more points of each label than the cell has inside: the vote runs to the end and
  // counts exactly what the full vote counts.
  const TriangleSoup soup = triangulate(test::l_building());
  const SurfaceIndex index(soup);
  const auto pts = random_points(5000, {-1, -1, -1}, {13, 13, 7}, 7);
  const size_t truth = count_inside(pts, in_l);
  Exact oracle{in_l};
  size_t classified = 0;
  const RegionCount count = region_vote(pts, 0, 9, index, index.touching(box_of(pts)), 0.01, BBox{},
                                        oracle.fn(), classified, truth + 1);
  EXPECT_TRUE(count.complete);
  EXPECT_EQ(count.in, truth);
  EXPECT_EQ(count.out, pts.size() - truth);
}

TEST(RegionVote, IsDeterministic) {
  const TriangleSoup soup = triangulate(test::l_building());
  const SurfaceIndex index(soup);
  const auto pts = random_points(5000, {-1, -1, -1}, {13, 13, 7}, 5);
  std::vector<uint64_t> first, second;
  for (auto* seen : {&first, &second}) {
    const PointClassifier record = [&](const std::vector<Vec3>& q, const std::vector<uint64_t>& ids,
                                       std::vector<uint8_t>& out) {
      out.resize(q.size());
      for (size_t i = 0; i < q.size(); ++i) out[i] = in_l(q[i]);
      seen->insert(seen->end(), ids.begin(), ids.end());
    };
    size_t classified = 0;
    region_vote(pts, 100, 9, index, index.touching(box_of(pts)), 0.01, BBox{}, record, classified);
  }
  EXPECT_EQ(first, second);
}

}  // namespace
}  // namespace mc
