// The small building blocks of the pipeline: measurements, hashing, solid encoding, progress.
#include <cmath>

#include "pipeline/measures.hpp"
#include "pipeline/part_objects.hpp"
#include "pipeline/progress.hpp"
#include "pipeline/sha256.hpp"
#include "pipeline/solid_check.hpp"
#include "pipeline/summary_csv.hpp"
#include "pipeline_fixtures.hpp"

namespace mc::pipeline {
namespace {

// Axis-aligned box [o, o + d], outward faces, labelled like a building.
PolygonMesh box(Vec3 o, Vec3 d) {
  PolygonMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.push_back({o.x + (i & 1) * d.x, o.y + ((i >> 1) & 1) * d.y, o.z + ((i >> 2) & 1) * d.z});
  auto face = [&](std::vector<uint32_t> r, const char* l) {
    Polygon p;
    p.rings.push_back(std::move(r));
    p.semantic = m.label_index(l);
    m.faces.push_back(std::move(p));
  };
  face({0, 2, 3, 1}, "GroundSurface");
  face({4, 5, 7, 6}, "RoofSurface");
  face({0, 1, 5, 4}, "WallSurface");
  face({2, 6, 7, 3}, "WallSurface");
  face({0, 4, 6, 2}, "WallSurface");
  face({1, 3, 7, 5}, "ClosureSurface");
  return m;
}

TEST(Measures, VolumeCentroidFootprintHeightOfABoxFarFromTheOrigin) {
  const PolygonMesh m = box({85000, 446000, -2}, {10, 20, 6});
  const VolumeCentroid vc = volume_centroid(m);
  EXPECT_NEAR(vc.volume, 1200, 1e-6);
  EXPECT_NEAR(vc.centroid.x, 85005, 1e-6);
  EXPECT_NEAR(vc.centroid.y, 446010, 1e-6);
  EXPECT_NEAR(vc.centroid.z, 1, 1e-6);
  const Footprint fp = footprint(m);
  EXPECT_EQ(fp.method, "ground");
  EXPECT_NEAR(fp.area, 200, 1e-9);
  EXPECT_NEAR(*height(m), 6, 1e-12);
  EXPECT_NEAR(bbox_centre(m)->z, 1, 1e-12);
  // Two boxes = sum; an inward-facing copy has negative volume.
  const VolumeCentroid two =
      volume_centroid(std::vector<PolygonMesh>{m, box({85010, 446000, -2}, {10, 20, 6})});
  EXPECT_NEAR(two.volume, 2400, 1e-6);
  EXPECT_NEAR(two.centroid.x, 85010, 1e-6);
}

TEST(Measures, FootprintFallsBackToTheConvexHullWithoutGround) {
  PolygonMesh m = box({0, 0, 0}, {4, 3, 2});
  m.semantic_labels[0] = "FloorSurface";  // no GroundSurface left
  const Footprint fp = footprint(m);
  EXPECT_EQ(fp.method, "hull");
  EXPECT_NEAR(fp.area, 12, 1e-12);
  EXPECT_NEAR(hull_area_2d({{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {1, 1, 5}, {1, 0, 0}}), 4, 1e-12);
}

TEST(Measures, ProjectedAreaSubtractsHoles) {
  PolygonMesh m;
  for (Vec3 v : {Vec3{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {1, 1, 0}, {1, 2, 0}, {2, 2, 0}, {2, 1, 0}})
    m.vertices.push_back(v);
  Polygon p;
  p.rings = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  EXPECT_NEAR(projected_area(m, p), 15, 1e-12);
}

TEST(Sha256, KnownVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  Sha256 s;  // a million 'a's in uneven chunks
  const std::string chunk(997, 'a');
  size_t left = 1000000;
  while (left) {
    const size_t n = std::min(left, chunk.size());
    s.update(chunk.data(), n);
    left -= n;
  }
  EXPECT_EQ(s.hex(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

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
  PolygonMesh m = box({85000.00012, 446000, 0}, {10, 20, 6});
  const EncodedSolid a = encode_solid(m, "2.2", "2.0", pool);
  EXPECT_EQ(closed_shell_defect(a.shell), "");
  EXPECT_EQ(out.size(), 9u);
  EXPECT_NEAR(out[1].x, 85000.0, 1e-9);  // snapped to the mm grid
  EXPECT_EQ(a.geometry["lod"], "2.2");
  EXPECT_EQ(a.geometry["semantics"]["surfaces"].size(), 4u);
  EXPECT_EQ(a.geometry["semantics"]["values"][0].size(), 6u);
  // A second part sharing a face reuses the vertices on the grid.
  const EncodedSolid b = encode_solid(box({85010, 446000, 0}, {10, 20, 6}), "2.2", "2.0", pool);
  EXPECT_EQ(out.size(), 13u);
  // A face thinner than the grid collapses and is dropped, counted.
  PolygonMesh thin = box({85000, 446000, 0}, {10, 0.0001, 6});
  const EncodedSolid c = encode_solid(thin, "2", "1.0", pool);
  EXPECT_GT(c.dropped_faces, 0u);
  EXPECT_TRUE(c.geometry["lod"].is_number());
}

TEST(Summary, ColumnsNameEveryWrittenLevel) {
  const auto c = summary_columns({0.1, 0.001});
  EXPECT_EQ(c[0], "id");
  EXPECT_NE(std::find(c.begin(), c.end(), "parts_0.1"), c.end());
  EXPECT_NE(std::find(c.begin(), c.end(), "parts_0.001"), c.end());
  for (const char* s :
       {"height", "footprint_area", "volume", "convexity", "mean_part_convexity", "largest_part_share",
        "max_degree", "end_parts", "centroid_x", "centroid_y", "centroid_z", "lon", "lat"})
    EXPECT_NE(std::find(c.begin(), c.end(), s), c.end()) << s;
}

TEST(Progress, ShowsDoneTotalRateAndEta) {
  const std::string line = Progress::render(100, 400, 2, 10.0);
  EXPECT_NE(line.find("100/400"), std::string::npos) << line;
  EXPECT_NE(line.find("10.0/s"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 0:30"), std::string::npos) << line;
  EXPECT_NE(line.find("2 not ok"), std::string::npos) << line;
  EXPECT_NE(Progress::render(5, std::nullopt, 0, 2.0).find("5 features"), std::string::npos);
}

}  // namespace
}  // namespace mc::pipeline
