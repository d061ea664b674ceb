// Building measures of the job (pipeline/measures.hpp) and the progress line (pipeline/progress.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "tests/core/labelled_box.hpp"
#include "pipeline/measures.hpp"
#include "pipeline/progress.hpp"

namespace {

using namespace mc;
using namespace mc::pipeline;

TEST(Measures, VolumeCentroidFootprintHeightOfABoxFarFromTheOrigin) {
  const PolygonMesh m = mc::test::labelled_box({85000, 446000, -2}, {10, 20, 6});
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
      volume_centroid(std::vector<PolygonMesh>{m, mc::test::labelled_box({85010, 446000, -2}, {10, 20, 6})});
  EXPECT_NEAR(two.volume, 2400, 1e-6);
  EXPECT_NEAR(two.centroid.x, 85010, 1e-6);
}

TEST(Measures, FootprintFallsBackToTheConvexHullWithoutGround) {
  PolygonMesh m = mc::test::labelled_box({0, 0, 0}, {4, 3, 2});
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

TEST(Progress, ShowsDoneTotalRateAndEta) {
  const std::string line = Progress::render(100, 400, 2, 10.0);
  EXPECT_NE(line.find("100/400"), std::string::npos) << line;
  EXPECT_NE(line.find("10.0/s"), std::string::npos) << line;
  EXPECT_NE(line.find("ETA 0:30"), std::string::npos) << line;
  EXPECT_NE(line.find("2 not ok"), std::string::npos) << line;
  EXPECT_NE(Progress::render(5, std::nullopt, 0, 2.0).find("5 features"), std::string::npos);
}

}  // namespace
