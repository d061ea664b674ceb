// Inside/outside oracle: closed, open-bottom, flipped and duplicated inputs; shared-edge hits
// counted once; determinism; throughput on the largest sample.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "core/oracle.hpp"
#include "core/soup.hpp"
#include "off_fixture.hpp"
#include "buildings.hpp"
#include "synthetic_buildings.hpp"

namespace mc {
namespace {

// Points of the L-prism's bounding box [0,10]x[0,8]x[0,6]: inside the L, or in its notch
// (x > 4 and y > 4), kept 0.05 away from every face.
struct Probe {
  Vec3 p;
  bool inside;
};
std::vector<Probe> l_probes() {
  std::vector<Probe> out;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> ux(0, 10), uy(0, 8), uz(0, 6);
  while (out.size() < 2000) {
    const Vec3 p{ux(rng), uy(rng), uz(rng)};
    auto near = [](double v, double w) { return std::abs(v - w) < 0.05; };
    if (near(p.x, 0) || near(p.x, 10) || near(p.x, 4) || near(p.y, 0) || near(p.y, 8) || near(p.y, 4) ||
        near(p.z, 0) || near(p.z, 6))
      continue;
    out.push_back({p, !(p.x > 4 && p.y > 4)});
  }
  // And points outside the bounding box, above, below and beside.
  for (Vec3 p : {Vec3{2, 2, 7}, Vec3{2, 2, -1}, Vec3{-1, 2, 3}, Vec3{11, 2, 3}, Vec3{7, 6, 100}})
    out.push_back({p, false});
  return out;
}

int misclassified(const PolygonMesh& m, int rays = 7, uint64_t seed = 1) {
  const InsideOracle oracle(triangulate(m), rays, seed);
  int wrong = 0;
  const auto probes = l_probes();
  for (size_t i = 0; i < probes.size(); ++i) wrong += oracle.inside(probes[i].p, i) != probes[i].inside;
  return wrong;
}

TEST(Oracle, ClosedLPrism) { EXPECT_EQ(misclassified(test::l_prism()), 0); }

TEST(Oracle, OpenBottomLPrism) { EXPECT_EQ(misclassified(test::l_prism(false)), 0); }

// The fast path for valid solids (docs/algorithm.md §6.6): a clean first ray decides a
// point. On a valid solid it labels like the vote, also for points whose rays run through the
// L's edges and vertices (those fall back to the vote).
TEST(Oracle, ValidSolidFastPathLabelsLikeTheVote) {
  const TriangleSoup soup = triangulate(test::l_prism());
  InsideOracle vote(soup, 5, 1), fast(soup, 5, 1);
  fast.set_valid_solid(true);
  const auto probes = l_probes();
  int wrong = 0, differ = 0;
  for (size_t i = 0; i < probes.size(); ++i) {
    wrong += fast.inside(probes[i].p, i) != probes[i].inside;
    differ += fast.inside(probes[i].p, i) != vote.inside(probes[i].p, i);
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(differ, 0);
  // A ray up from inside that leaves through the middle of the roof is clean; one aimed at the
  // roof corner above the notch (4, 4, 6), where walls and roof meet, is not.
  bool clean = false;
  EXPECT_EQ(fast.count_crossings({2, 1, 3}, {0.01, 0.02, 1}, &clean) & 1, 1);
  EXPECT_TRUE(clean);
  fast.count_crossings({2, 2, 3}, {2, 2, 3}, &clean);
  EXPECT_FALSE(clean);
}

// The fast path's rule (docs/algorithm.md §6.6), checked point by point against the rays it
// casts: on a valid solid a clean first ray decides; where the soup has a thin wedge (two faces
// meeting at less than 45°), a second clean ray has to agree, and otherwise the vote decides.
struct FirstRays {
  bool clean0, clean1;
  int n0, n1;
};
FirstRays first_rays(const InsideOracle& o, const Vec3& p, uint64_t id) {
  FirstRays r{};
  r.n0 = o.count_crossings(p, o.ray(id, 0), &r.clean0) & 1;
  r.n1 = o.count_crossings(p, o.ray(id, 1), &r.clean1) & 1;
  return r;
}

TEST(Oracle, ValidSolidWithoutThinWedgesIsDecidedByACleanFirstRay) {
  const TriangleSoup soup = triangulate(test::l_prism());
  InsideOracle vote(soup, 5, 1), fast(soup, 5, 1);
  for (InsideOracle* o : {&vote, &fast}) o->set_merge_distance(1.0);
  fast.set_valid_solid(true);
  EXPECT_FALSE(fast.thin_wedges());
  const auto probes = l_probes();
  int clean = 0;
  for (size_t i = 0; i < probes.size(); ++i) {
    const FirstRays r = first_rays(fast, probes[i].p, i);
    clean += r.clean0;
    EXPECT_EQ(fast.inside(probes[i].p, i), r.clean0 ? r.n0 == 1 : vote.inside(probes[i].p, i)) << i;
  }
  EXPECT_GT(clean, 1000);  // (nearly all: the L has no thin place for a ray to pass)
}

// Beside a wedge thinner than the merge distance, rays that cross the wedge see its two faces as
// one crossing, and the vote calls outside points inside; the fast path keeps the vote's
// semantics there unless two clean rays agree. The probes' first rays (azimuth 0°..72°) leave
// towards +x, away from the wedge, and are clean: one ray would call them outside.
TEST(Oracle, ValidSolidWithAThinWedgeNeedsTwoCleanRaysThatAgree) {
  PolygonMesh m;
  test::add_prism(m, {{0, 0}, {0.05, 10}, {0, 10}}, 0, 10);  // 0 < x < 0.005 y: a 0.3° wedge
  const TriangleSoup soup = triangulate(m);
  InsideOracle vote(soup, 5, 1), fast(soup, 5, 1);
  for (InsideOracle* o : {&vote, &fast}) o->set_merge_distance(0.1);
  fast.set_valid_solid(true);
  EXPECT_TRUE(fast.thin_wedges());
  int one_ray_differs = 0;
  uint64_t id = 0;
  for (double y : {2.0, 4.0, 6.0, 8.0})
    for (double dx : {0.002, 0.005, 0.01})
      for (double z : {2.0, 5.0, 8.0}) {
        const Vec3 p{0.005 * y + dx, y, z};  // outside, inside the wedge's bounding box
        const FirstRays r = first_rays(fast, p, id);
        const bool two = r.clean0 && r.clean1 && r.n0 == r.n1 ? r.n0 == 1 : vote.inside(p, id);
        EXPECT_EQ(fast.inside(p, id), two) << "y " << y << " dx " << dx << " z " << z;
        one_ray_differs += r.clean0 && (r.n0 == 1) != two;
        ++id;
      }
  EXPECT_GT(one_ray_differs, 0);  // the probes where the second ray matters are there
}

TEST(Oracle, FlippedAndDuplicatedFaces) {
  PolygonMesh m = test::as_mesh(triangulate(test::l_prism(false)), test::l_prism(false));
  for (size_t f = 0; f < m.faces.size(); f += 3) test::flip_face(m, f);
  const size_t n = m.faces.size();
  for (size_t f = 0; f < n; f += 2) m.faces.push_back(m.faces[f]);  // coincident duplicates
  EXPECT_EQ(misclassified(m), 0);
}

// Two closed shells glued along a shared vertical edge and overlapping (a box and a triangular
// prism through its corner, as in some Hong Kong inputs): parity over the glued union calls the
// overlap outside; each shell is its own parity group, so the overlap is inside.
TEST(Oracle, OverlappingShellsGluedAlongAnEdge) {
  PolygonMesh m;
  test::add_prism(m, {{0, 0}, {2, 0}, {2, 2}, {0, 2}}, 0, 2);
  test::add_prism(m, {{2, 2}, {0.5, 3}, {3, 0.5}}, 0, 2);
  const TriangleSoup soup = triangulate(clean_soup(m, 1e-9, nullptr));
  const InsideOracle oracle(soup, 7, 1);
  uint64_t id = 0;
  EXPECT_TRUE(oracle.inside({1.85, 1.85, 1}, id++));     // in both shells
  EXPECT_TRUE(oracle.inside({0.5, 0.5, 1}, id++));       // in the box only
  EXPECT_TRUE(oracle.inside({2.3, 1.4, 1}, id++));       // in the prism only, beside the box
  EXPECT_FALSE(oracle.inside({1.85, 1.85, 2.5}, id++));  // above both
  EXPECT_FALSE(oracle.inside({2.8, 2.8, 1}, id++));      // beside the shared edge, outside both
}

// Two storeys whose floor is one sheet inside the solid, glued to the walls along the z = 3 ring
// (edges of three faces), as in sample17's stacked storeys. An upward ray from the lower storey
// crosses the sheet and the roof: even parity, "outside". No ray from there escapes, so with the
// enclosure fallback it is inside. With the lower storey's east wall missing (an open arcade)
// rays escape through it and the storey stays outside.
PolygonMesh storeys_with_floor_sheet(bool east_wall_below) {
  PolygonMesh m;
  const double xy[4][2] = {{0, 0}, {10, 0}, {10, 8}, {0, 8}};
  for (double z : {0.0, 3.0, 6.0})
    for (const auto& c : xy) test::add_vertex(m, {c[0], c[1], z});
  auto v = [](int level, int corner) { return static_cast<uint32_t>(4 * level + corner % 4); };
  for (int level = 0; level < 2; ++level)
    for (int k = 0; k < 4; ++k) {
      if (level == 0 && k == 1 && !east_wall_below) continue;  // the wall x = 10, from (10,0) to (10,8)
      test::add_face(m, {v(level, k), v(level, k + 1), v(level + 1, k + 1), v(level + 1, k)}, "WallSurface");
    }
  test::add_face(m, {v(0, 3), v(0, 2), v(0, 1), v(0, 0)}, "GroundSurface");
  test::add_face(m, {v(1, 0), v(1, 1), v(1, 2), v(1, 3)}, "FloorSurface");  // the interior sheet
  test::add_face(m, {v(2, 0), v(2, 1), v(2, 2), v(2, 3)}, "RoofSurface");
  return m;
}

TEST(Oracle, EnclosedStoreyBelowAFloorSheetIsInside) {
  const TriangleSoup soup = triangulate(storeys_with_floor_sheet(true));
  InsideOracle oracle(soup, 7, 1);
  EXPECT_EQ(oracle.nonmanifold_edges(), 4u);
  const Vec3 lower{5, 4, 1.5}, upper{5, 4, 4.5};
  EXPECT_FALSE(oracle.inside(lower, 0));  // parity alone gets it wrong
  EXPECT_TRUE(oracle.inside(upper, 1));
  EXPECT_TRUE(oracle.enclosed(lower, 0));
  oracle.set_enclosure(true);
  for (uint64_t id = 0; id < 50; ++id) {
    EXPECT_TRUE(oracle.inside({1 + 0.16 * id, 4, 1.5}, id));
    EXPECT_TRUE(oracle.inside({1 + 0.16 * id, 4, 4.5}, id));
  }
  EXPECT_FALSE(oracle.inside({5, 4, 6.5}, 100));  // outside the bounding box

  InsideOracle open(triangulate(storeys_with_floor_sheet(false)), 7, 1);
  open.set_enclosure(true);
  EXPECT_FALSE(open.enclosed(lower, 0));
  EXPECT_FALSE(open.inside(lower, 0));
  EXPECT_TRUE(open.inside(upper, 1));
}

// Without edges of three or more faces there are no interior sheets: asking for the fallback
// leaves it off, and the open-bottom L is classified by parity alone, exactly.
TEST(Oracle, EnclosureStaysOffWithoutNonManifoldEdges) {
  InsideOracle oracle(triangulate(test::l_prism(false)), 7, 1);
  EXPECT_EQ(oracle.nonmanifold_edges(), 0u);
  oracle.set_enclosure(true);
  const auto probes = l_probes();
  int wrong = 0;
  for (size_t i = 0; i < probes.size(); ++i) wrong += oracle.inside(probes[i].p, i) != probes[i].inside;
  EXPECT_EQ(wrong, 0);
}

TEST(Oracle, JitteredSoupWithOneRay) {
  PolygonMesh m = test::explode(test::as_mesh(triangulate(test::l_prism()), test::l_prism()));
  test::jitter(m, 0.001, 9);           // cracks of up to 2 mm between faces
  EXPECT_LE(misclassified(m, 1), 10);  // a single ray may slip through a crack
  EXPECT_EQ(misclassified(m, 7), 0);
}

TEST(Oracle, SharedEdgesAndVerticesCountOnce) {
  const TriangleSoup s = triangulate(test::box({0, 0, 0}, {2, 2, 2}));  // quads split on a diagonal
  const InsideOracle oracle(s, 1, 1);
  // Straight up through the centre of the top face: that is on the split diagonal.
  EXPECT_EQ(oracle.count_crossings({1, 1, 1}, {0, 0, 1}), 1);
  // Through the top face's corner vertex (shared by 2 top triangles and 4 wall triangles).
  EXPECT_EQ(oracle.count_crossings({1, 1, 1}, normalized(Vec3{1, 1, 1})), 1);
  // Through a vertical edge between two walls, from outside: in and out.
  EXPECT_EQ(oracle.count_crossings({-1, -1, 1}, normalized(Vec3{1, 1, 0})), 2);
  EXPECT_EQ(oracle.count_crossings({1, 1, 3}, {0, 0, 1}), 0);
}

TEST(Oracle, GableHouseOpenBottom) {
  const InsideOracle oracle(triangulate(test::gable_house(10, 8, 4, 7, false, false)), 7, 3);
  EXPECT_TRUE(oracle.inside({5, 4, 6.5}, 0));     // in the attic, under the ridge
  EXPECT_FALSE(oracle.inside({5, 0.5, 6.5}, 1));  // above the roof slope, inside the bbox
  EXPECT_TRUE(oracle.inside({0.1, 0.1, 0.1}, 2));
}

TEST(Oracle, DeterministicAndIndependentOfBatching) {
  const InsideOracle oracle(triangulate(test::l_prism(false)), 7, 42);
  std::vector<Vec3> pts;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1, 11);
  for (int i = 0; i < 20000; ++i) pts.push_back({u(rng), u(rng) * 0.8, u(rng) * 0.6});
  std::vector<uint8_t> a, b;
  oracle.classify(pts, 100, a);
  oracle.classify(pts, 100, b);
  EXPECT_EQ(a, b);
  for (size_t i = 0; i < pts.size(); i += 97) EXPECT_EQ(a[i], oracle.inside(pts[i], 100 + i) ? 1 : 0);
  const InsideOracle again(triangulate(test::l_prism(false)), 7, 42);
  std::vector<uint8_t> c;
  again.classify(pts, 100, c);
  EXPECT_EQ(a, c);
}

TEST(Oracle, EmptySoupIsOutside) {
  const InsideOracle oracle(TriangleSoup{}, 7, 1);
  EXPECT_FALSE(oracle.inside({0, 0, 0}, 0));
}

// Georeferenced coordinates (~8e5) must not break the float ray caster.
TEST(Oracle, LargeCoordinates) {
  PolygonMesh m = test::l_prism(false);
  translate(m, {835000, 815000, 30});
  const InsideOracle oracle(triangulate(m), 7, 1);
  EXPECT_TRUE(oracle.inside({835001, 815001, 31}, 0));
  EXPECT_FALSE(oracle.inside({835007, 815006, 31}, 1));
}

// The vote casts its first rays as one Embree packet; its labels are the majority of the same
// rays cast one by one, on a real sample that is not a valid solid (its shell is not closed).
TEST(Oracle, PacketVoteIsTheMajorityOfSingleRays) {
  const auto all = test::samples();
  ASSERT_GE(all.size(), 16u);
  for (const auto& s : all) {
    if (s.name != "sample2" && s.name != "sample13") continue;
    PolygonMesh m = clean_soup(test::load_off(s.off.string()), 1e-6, nullptr);
    translate(m, -bbox_center(m));
    const InsideOracle oracle(triangulate(m), 5, 3);
    std::mt19937_64 rng(4);
    const BBox& b = oracle.bbox();
    std::uniform_real_distribution<double> ux(b.lo.x, b.hi.x), uy(b.lo.y, b.hi.y), uz(b.lo.z, b.hi.z);
    int inside = 0;
    for (uint64_t id = 0; id < 3000; ++id) {
      const Vec3 p{ux(rng), uy(rng), uz(rng)};
      int votes = 0;
      for (int k = 0; k < 5; ++k) votes += oracle.count_crossings(p, oracle.ray(id, k)) & 1;
      ASSERT_EQ(oracle.inside(p, id), 2 * votes > 5) << s.name << " point " << id;
      inside += 2 * votes > 5;
    }
    EXPECT_GT(inside, 150) << s.name;
    EXPECT_LT(inside, 2850) << s.name;
  }
}

TEST(Oracle, SamplesThroughput) {
  const auto all = test::samples();
  ASSERT_GE(all.size(), 16u);
  for (const auto& s : all) {
    if (s.name != "sample17" && s.name != "sample2") continue;  // largest and a small house
    PolygonMesh m = clean_soup(test::load_off(s.off.string()), 1e-6, nullptr);
    translate(m, -bbox_center(m));
    const TriangleSoup soup = triangulate(m);
    const auto t0 = std::chrono::steady_clock::now();
    const InsideOracle oracle(soup, 7, 1);
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<Vec3> pts;
    std::mt19937_64 rng(2);
    const BBox& b = oracle.bbox();
    std::uniform_real_distribution<double> ux(b.lo.x, b.hi.x), uy(b.lo.y, b.hi.y), uz(b.lo.z, b.hi.z);
    for (int i = 0; i < 200000; ++i) pts.push_back({ux(rng), uy(rng), uz(rng)});
    std::vector<uint8_t> in;
    oracle.classify(pts, 0, in);
    const auto t2 = std::chrono::steady_clock::now();
    const double frac = std::count(in.begin(), in.end(), 1) / double(in.size());
    // A building fills a sizeable but partial share of its bounding box.
    EXPECT_GT(frac, 0.05) << s.name;
    EXPECT_LT(frac, 0.95) << s.name;
    const double secs = std::chrono::duration<double>(t2 - t1).count();
    std::printf("[ oracle   ] %s: %zu triangles, build %.1f ms, %.0f points/s (7 rays), inside %.3f\n",
                s.name.c_str(), soup.triangles.size(),
                std::chrono::duration<double, std::milli>(t1 - t0).count(), pts.size() / secs, frac);
  }
}

}  // namespace
}  // namespace mc
