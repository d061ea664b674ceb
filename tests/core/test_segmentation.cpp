// Plane segmentation: expected plane counts on synthetic buildings, independence of face
// orientation, merging of coplanar pieces, area filter, and sanity on every real sample.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <set>

#include "core/segmentation.hpp"
#include "core/soup.hpp"
#include "off_fixture.hpp"
#include "synthetic_buildings.hpp"

namespace mc {
namespace {

SegmentationParams params(double dist = 0.05, double angle = 10, double min_area = 0.01) {
  SegmentationParams p;
  p.max_distance = p.dist_thresh = dist;
  p.max_angle_deg = p.angle_thresh_deg = angle;
  p.min_area = min_area;
  return p;
}

// Regions as (canonical plane rounded, face set): comparable across orientation changes.
std::set<std::vector<uint32_t>> face_sets(const std::vector<PlaneRegion>& rs) {
  std::set<std::vector<uint32_t>> out;
  for (const auto& r : rs) out.insert(r.faces);
  return out;
}

void expect_partition(const std::vector<PlaneRegion>& rs, size_t n_faces) {
  std::vector<int> seen(n_faces, 0);
  for (size_t i = 0; i < rs.size(); ++i) {
    EXPECT_NEAR(norm(rs[i].plane.n), 1.0, 1e-9);
    if (i > 0) { EXPECT_GE(rs[i - 1].area, rs[i].area); }
    EXPECT_TRUE(std::is_sorted(rs[i].faces.begin(), rs[i].faces.end()));
    for (uint32_t f : rs[i].faces) ++seen.at(f);
  }
  for (int s : seen) EXPECT_LE(s, 1);
}

TEST(Segmentation, SyntheticPlaneCounts) {
  const PolygonMesh box = test::box({0, 0, 0}, {10, 8, 6});
  const PolygonMesh l = test::l_prism();
  const PolygonMesh house = test::gable_house();
  EXPECT_EQ(segment_planes(box, params()).size(), 6u);
  EXPECT_EQ(segment_planes(l, params()).size(), 8u);
  EXPECT_EQ(segment_planes(house, params()).size(), 7u);
  EXPECT_EQ(segment_planes(test::l_prism(false), params()).size(), 7u);
  // Triangulated: regions must grow across the triangles.
  for (const PolygonMesh* m : {&box, &l, &house}) {
    const PolygonMesh tri = test::as_mesh(triangulate(*m), *m);
    const auto rs = segment_planes(tri, params());
    EXPECT_EQ(rs.size(), m->faces.size());
    expect_partition(rs, tri.faces.size());
    size_t assigned = 0;
    for (const auto& r : rs) assigned += r.faces.size();
    EXPECT_EQ(assigned, tri.faces.size());
  }
}

TEST(Segmentation, PlanesAndAreasAreRight) {
  const auto rs = segment_planes(test::l_prism(), params());
  ASSERT_EQ(rs.size(), 8u);
  // Largest first: the 10 x 6 wall (60), floor and roof (56 each), then the other walls.
  EXPECT_NEAR(rs[0].area, 60, 1e-9);
  EXPECT_NEAR(std::abs(rs[0].plane.n.y), 1, 1e-12);
  EXPECT_NEAR(rs[1].area, 56, 1e-9);
  EXPECT_NEAR(rs[2].area, 56, 1e-9);
  for (int i : {1, 2}) {
    EXPECT_NEAR(std::abs(rs[i].plane.n.z), 1, 1e-12);
    const double z = -rs[i].plane.d / rs[i].plane.n.z;
    EXPECT_TRUE(std::abs(z) < 1e-9 || std::abs(z - 6) < 1e-9) << z;
  }
  // Majority orientation follows the (outward) faces: the roof normal points up.
  for (const auto& r : rs)
    if (r.bbox.lo.z > 5) { EXPECT_GT(r.plane.n.z, 0.99); }
  // Semantic labels: roof region labelled Roof.
  const PolygonMesh m = test::l_prism();
  for (const auto& r : rs) EXPECT_EQ(r.semantic, m.faces[r.faces[0]].semantic);
}

TEST(Segmentation, IndependentOfFaceOrientation) {
  PolygonMesh tri = test::as_mesh(triangulate(test::gable_house()), test::gable_house());
  const auto ref = segment_planes(tri, params());
  for (size_t f = 0; f < tri.faces.size(); f += 2) test::flip_face(tri, f);  // every other triangle
  const auto flipped = segment_planes(tri, params());
  EXPECT_EQ(flipped.size(), 7u);
  EXPECT_EQ(face_sets(flipped), face_sets(ref));
  for (size_t i = 0; i < ref.size(); ++i) {
    Plane a = ref[i].plane, b = flipped[i].plane;
    ASSERT_TRUE(canonicalize(a) && canonicalize(b));
    EXPECT_NEAR(norm(a.n - b.n), 0, 1e-9);
    EXPECT_NEAR(a.d, b.d, 1e-9);
  }
}

TEST(Segmentation, DuplicateFacesJoinTheirPlane) {
  PolygonMesh m = test::l_prism();
  const size_t n = m.faces.size();
  for (size_t f = 0; f < n; ++f) {
    m.faces.push_back(m.faces[f]);
    test::flip_face(m, m.faces.size() - 1);  // an inward duplicate of every face
  }
  const auto rs = segment_planes(m, params());
  EXPECT_EQ(rs.size(), 8u);
  for (const auto& r : rs) EXPECT_EQ(r.faces.size(), 2u);
}

TEST(Segmentation, JitteredSoupKeepsCounts) {
  PolygonMesh house = test::explode(test::as_mesh(triangulate(test::gable_house()), test::gable_house()));
  test::jitter(house, 0.001, 3);
  const PolygonMesh m = clean_soup(house, 0.005, nullptr);
  EXPECT_EQ(segment_planes(m, params(0.05)).size(), 7u);
  // Without vertex merging nothing is adjacent; the near-duplicate merge still joins the walls.
  EXPECT_EQ(segment_planes(house, params(0.05)).size(), 7u);
}

TEST(Segmentation, CoplanarPiecesMergeParallelWallsDoNot) {
  // Two halves of a wall (split by a window strip) and a parallel wall 1 m behind.
  PolygonMesh m;
  auto quad = [&](double x0, double x1, double y, double z0, double z1) {
    const uint32_t a = test::add_vertex(m, {x0, y, z0}), b = test::add_vertex(m, {x1, y, z0}),
                   c = test::add_vertex(m, {x1, y, z1}), d = test::add_vertex(m, {x0, y, z1});
    test::add_face(m, {a, b, c, d}, "WallSurface");
  };
  quad(0, 4, 0, 0, 3);
  quad(5, 9, 0.01, 0, 3);  // 1 cm off: within dist_thresh, a separate region when grown
  quad(0, 9, 1, 0, 3);
  const auto rs = segment_planes(m, params(0.05));
  ASSERT_EQ(rs.size(), 2u);
  EXPECT_EQ(rs[0].faces, (std::vector<uint32_t>{2}));  // 27 m² before the halves' 24 m²
  EXPECT_EQ(rs[1].faces, (std::vector<uint32_t>{0, 1}));
  EXPECT_NEAR(rs[1].area, 24, 1e-9);
  // Refit after merge: the merged plane passes through the halves' common centroid.
  EXPECT_NEAR(rs[1].plane.signed_distance({4.5, 0.005, 1.5}), 0, 1e-9);
  EXPECT_GT(std::abs(rs[1].plane.n.y), 0.999);
  // A wider angle threshold does not merge walls 1 m apart either.
  EXPECT_EQ(segment_planes(m, params(0.05, 45)).size(), 2u);
  EXPECT_EQ(segment_planes(m, params(1.5, 10)).size(), 1u);  // unless δ spans them
}

TEST(Segmentation, AreaFilterDropsSmallPlanes) {
  PolygonMesh m = test::box({0, 0, 0}, {10, 10, 5});
  const uint32_t a = test::add_vertex(m, {2, 2, 5}), b = test::add_vertex(m, {2.3, 2, 5.3}),
                 c = test::add_vertex(m, {2, 2.3, 5.3});
  test::add_face(m, {a, b, c}, "RoofSurface");  // a tiny inclined chimney face
  EXPECT_EQ(segment_planes(m, params(0.05, 10, 0.0)).size(), 7u);
  const auto rs = segment_planes(m, params(0.05, 10, 0.25));  // cell size 0.5
  EXPECT_EQ(rs.size(), 6u);
  for (const auto& r : rs) EXPECT_GE(r.area, 0.25);
}

TEST(Segmentation, MinRegionReleasesSmallRegions) {
  const PolygonMesh tri =
      test::as_mesh(triangulate(test::box({0, 0, 0}, {1, 1, 1})), test::box({0, 0, 0}, {1, 1, 1}));
  SegmentationParams p = params();
  p.min_region = 3;  // every face is 2 triangles: no region is large enough
  EXPECT_TRUE(segment_planes(tri, p).empty());
  p.min_region = 2;
  EXPECT_EQ(segment_planes(tri, p).size(), 6u);
}

TEST(Segmentation, Deterministic) {
  PolygonMesh m = test::as_mesh(triangulate(test::gable_house()), test::gable_house());
  test::jitter(m, 0.01, 11);
  const auto a = segment_planes(m, params(0.05));
  const auto b = segment_planes(m, params(0.05));
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].faces, b[i].faces);
    EXPECT_EQ(a[i].plane.n, b[i].plane.n);
    EXPECT_EQ(a[i].plane.d, b[i].plane.d);
  }
}

// The parameters of the paper's run.
SegmentationParams sample_params(const test::Sample& s) { return segmentation_params(test::paper_params(s)); }

TEST(Segmentation, EverySample) {
  const auto all = test::samples();
  ASSERT_GE(all.size(), 16u);
  double worst_ms = 0;
  std::string worst;
  for (const auto& s : all) {
    PolygonMesh m = clean_soup(test::load_off(s.off.string()), 1e-6, nullptr);
    translate(m, -bbox_center(m));
    const SegmentationParams p = sample_params(s);
    const auto t0 = std::chrono::steady_clock::now();
    const auto rs = segment_planes(m, p);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (ms > worst_ms) {
      worst_ms = ms;
      worst = s.name;
    }
    ASSERT_FALSE(rs.empty()) << s.name;
    expect_partition(rs, m.faces.size());
    double covered = 0, total = 0;
    for (const Polygon& f : m.faces) total += face_geometry(m, f).area;
    for (const auto& r : rs) {
      covered += r.area;
      EXPECT_GE(r.area, p.min_area) << s.name;
      // Every face vertex stays near its plane (merge refits may move it by up to δ).
      for (uint32_t f : r.faces)
        for (uint32_t v : m.faces[f].rings[0])
          EXPECT_LE(std::abs(r.plane.signed_distance(m.vertices[v])), p.max_distance + p.dist_thresh + 1e-9)
              << s.name;
    }
    // The planes explain most of the building surface.
    EXPECT_GT(covered, 0.8 * total) << s.name;
    // Close to the paper's own plane count (CGAL 6 region growing + pointer-ordered merge).
    const double rc = s.used.at("planar_region");
    EXPECT_LE(std::abs(static_cast<double>(rs.size()) - rc), std::max(3.0, 0.1 * rc)) << s.name;
    std::printf("[ segment  ] %-9s faces %5zu  planes %4zu (paper %3.0f)  covered %.3f  %.1f ms\n",
                s.name.c_str(), m.faces.size(), rs.size(), rc, covered / total, ms);
  }
  std::printf("[ segment  ] slowest: %s %.1f ms\n", worst.c_str(), worst_ms);
}

}  // namespace
}  // namespace mc
