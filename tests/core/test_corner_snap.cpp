// Corner snapping (core/corner_snap.hpp) and plane anchors in the exact complex.
#include "core/corner_snap.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

#include "buildings.hpp"
#include "core/complex.hpp"
#include "core/preprocess.hpp"
#include "core/soup.hpp"
#include "off_fixture.hpp"

namespace mc {
namespace {

PolygonMesh jittered(PolygonMesh m, double amount) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (Vec3& v : m.vertices) v += Vec3{u(rng), u(rng), u(rng)};
  return m;
}

struct Snapped {
  PolygonMesh mesh;
  std::vector<PlaneRegion> regions;
  std::vector<uint32_t> ids;
  PlaneRegistry reg;
  size_t anchored = 0;
};

void snap(Snapped& s, double tol) {
  SegmentationParams sp;
  sp.max_distance = sp.dist_thresh = 0.125;
  s.mesh = clean_soup(s.mesh, 0.0125, nullptr);
  s.regions = segment_planes(s.mesh, sp);
  for (const auto& r : s.regions) s.ids.push_back(s.reg.add(r.plane));
  s.anchored = snap_corners(s.mesh, s.regions, s.ids, s.reg, tol);
}

BBox box_of(const PolygonMesh& m) {
  BBox b;
  for (const Vec3& v : m.vertices) b.add(v);
  b.lo -= Vec3{1, 1, 1};
  b.hi += Vec3{1, 1, 1};
  return b;
}

// The cross gable's valley eave corners: two walls and two roof slopes meet at one input vertex.
// With 1 mm jitter the fitted planes miss one point by about 0.5 mm; each corner's fourth plane
// is anchored, and the exact complex then has it through the corner exactly.
TEST(CornerSnap, JitteredValleyCornersMeetExactly) {
  Snapped s;
  s.mesh = jittered(test::cross_gable_house(), 0.001);
  snap(s, 0.0125);
  ASSERT_EQ(s.anchored, 2u);
  CellComplex cx(s.reg, box_of(s.mesh));
  size_t checked = 0;
  for (uint32_t id = 0; id < s.reg.size(); ++id) {
    const auto* a = s.reg.anchor(id);
    if (!a) continue;
    // Carve down to the corner: split by the three anchor planes, then find their common vertex.
    std::vector<uint32_t> cells = cx.live_cells();
    for (uint32_t p : *a) {
      std::vector<uint32_t> next;
      for (uint32_t c : cells) {
        if (auto r = cx.split(c, p)) {
          next.push_back(r->neg);
          next.push_back(r->pos);
        } else {
          next.push_back(c);
        }
      }
      cells = next;
    }
    for (uint32_t v = 0; v < cx.num_vertices(); ++v) {
      if (cx.vertex_side(v, (*a)[0]) || cx.vertex_side(v, (*a)[1]) || cx.vertex_side(v, (*a)[2])) continue;
      EXPECT_EQ(cx.vertex_side(v, id), 0) << "anchored plane " << id << " misses its corner";
      // Its double offset agrees with the exact plane (for measurements).
      EXPECT_LT(std::abs(s.reg[id].signed_distance(cx.point(v))), 1e-12);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2u);
}

TEST(CornerSnap, CleanCornersAndFarPlanesAreLeftAlone) {
  // Without jitter the planes meet exactly (or to the last bit): nothing is needed at a box.
  Snapped box;
  box.mesh = test::box_building();
  snap(box, 0.0125);
  EXPECT_EQ(box.anchored, 0u);  // no corner of a box has four planes
  // With 5 cm jitter the misses exceed a tolerance of 1 mm: no plane is moved that far.
  Snapped rough;
  rough.mesh = jittered(test::cross_gable_house(), 0.05);
  snap(rough, 0.001);
  EXPECT_EQ(rough.anchored, 0u);
}

TEST(CornerSnap, RegistryRejectsBadAnchorsAndTheComplexRejectsCycles) {
  PlaneRegistry reg;
  const uint32_t x = reg.add({{1, 0, 0}, 0}), y = reg.add({{0, 1, 0}, 0}), z = reg.add({{0, 0, 1}, 0});
  const uint32_t w = reg.add({{1, 1, 1}, 0.001});
  EXPECT_THROW(reg.set_anchor(w, {w, x, y}, 0), std::invalid_argument);
  EXPECT_THROW(reg.set_anchor(w, {x, y, 99}, 0), std::invalid_argument);
  reg.set_anchor(w, {x, y, z}, 0);
  EXPECT_EQ(reg.num_anchored(), 1u);
  EXPECT_EQ(reg[w].d, 0.0);
  // A cycle (x anchored through w, w through x) cannot be built exactly.
  reg.set_anchor(x, {w, y, z}, 0);
  BBox b;
  b.add({-1, -1, -1});
  b.add({1, 1, 1});
  EXPECT_THROW(CellComplex(reg, b), std::logic_error);
}

// A missing wall's plane (not fitted: it goes through input edges) passing 1.9 mm from the line
// where two fitted walls' planes meet (the tile's 0503100000020703 with its party walls removed):
// the carving's hair rule would refuse it wherever that line bounds a cell. Line snapping anchors
// it on the line; in the exact complex every vertex on the line is then on the plane, and the
// plane moved by no more than the 1.9 mm. Lines not parallel to it, beyond the tolerance, or
// outside its box are left alone.
TEST(CornerSnap, MissingFacePlaneSnapsToAHairLine) {
  PlaneRegistry reg;
  // Two vertical walls meeting in the line x = 0, y = 0.0019 (tilted a little, as fitted planes
  // are), and the missing wall y = 0 along x.
  Plane a{normalized(Vec3{1, 0.02, 1e-17}), 0};
  a.d = -dot(a.n, Vec3{0, 0.0019, 0});
  Plane b{normalized(Vec3{0.3, 1, -2e-17}), 0};
  b.d = -dot(b.n, Vec3{0, 0.0019, 0});
  const uint32_t ia = reg.add(a), ib = reg.add(b);
  const uint32_t ground = reg.add({{0, 0, 1}, 0});
  const uint32_t missing = reg.add({{0, 1, 0}, 0});
  BBox where;  // the missing wall's box: x 0..8, y 0, z 0..6
  where.add({0, 0, 0});
  where.add({8, 0, 6});
  EXPECT_EQ(snap_to_lines({missing}, {where}, {ia, ib, ground}, reg, 0.0025, 0.01), 1u);
  ASSERT_NE(reg.line_anchor(missing), nullptr);
  EXPECT_NEAR(reg[missing].signed_distance({0, 0.0019, 3}), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(reg[missing].n.y), 1.0, 1e-9);
  // In the exact complex: split by both walls, then every vertex on their line is on the plane.
  BBox box;
  box.add({-2, -2, -1});
  box.add({10, 5, 7});
  CellComplex cx(reg, box);
  for (uint32_t p : {ia, ib}) {
    std::vector<uint32_t> cells = cx.live_cells();
    for (uint32_t c : cells) cx.split(c, p);
  }
  size_t on_line = 0;
  for (uint32_t v = 0; v < cx.num_vertices(); ++v) {
    if (cx.vertex_side(v, ia) || cx.vertex_side(v, ib)) continue;
    EXPECT_EQ(cx.vertex_side(v, missing), 0);
    ++on_line;
  }
  EXPECT_EQ(on_line, 2u);  // where the line meets the box's bottom and top

  // Left alone: a plane 5 mm from the line (beyond 2.5 mm), a line outside the box, and a line
  // not parallel to the plane (a roof meeting a wall).
  PlaneRegistry far;
  const uint32_t fa = far.add(a), fb = far.add(b), fm = far.add({{0, 1, 0}, 0.005 - 0.0019});
  EXPECT_EQ(snap_to_lines({fm}, {where}, {fa, fb}, far, 0.0025, 0.01), 0u);
  BBox elsewhere;
  elsewhere.add({3, 0, 0});
  elsewhere.add({8, 0, 6});
  PlaneRegistry out;
  const uint32_t oa = out.add(a), ob = out.add(b), om = out.add({{0, 1, 0}, 0});
  EXPECT_EQ(snap_to_lines({om}, {elsewhere}, {oa, ob}, out, 0.0025, 0.01), 0u);
  PlaneRegistry slanted;
  const uint32_t sa = slanted.add(a), sr = slanted.add({normalized(Vec3{0, 1, 1}), -0.0019 / std::sqrt(2.0)});
  const uint32_t sm = slanted.add({{0, 1, 0}, 0});
  EXPECT_EQ(snap_to_lines({sm}, {where}, {sa, sr}, slanted, 0.0025, 0.01), 0u);
}

// Real inputs whose fitted planes share corners: a 3D BAG building (automatic resolution) and
// sample22 (its paper parameters). Preprocessing anchors planes there, the cell stays a closed
// 2-manifold, and in the carved complex every anchored plane passes exactly through each vertex
// its three anchor planes meet in.
TEST(CornerSnap, RealInputsGetExactCornersAndClosedCells) {
  std::vector<std::pair<std::string, PreprocessParams>> inputs;
  PreprocessParams automatic;
  automatic.compute_hausdorff = false;
  inputs.push_back({std::string(MC_SOURCE_DIR) + "/tests/core/data/3dbag_0503100000004560.off", automatic});
  for (const auto& s : test::samples())
    if (s.name == "sample22") inputs.push_back({s.off.string(), test::paper_params(s)});
  ASSERT_EQ(inputs.size(), 2u);
  for (const auto& [path, p] : inputs) {
    SCOPED_TRACE(path);
    const Preprocessed pre = preprocess(test::load_off(path), p, Clock::now() + std::chrono::seconds(60));
    EXPECT_GT(pre.anchored_planes, 0u);
    EXPECT_TRUE(pre.closed && pre.manifold);
    const CellComplex& cx = *pre.complex;
    size_t corners = 0;
    for (uint32_t id = 0; id < pre.planes->size(); ++id) {
      const auto* a = pre.planes->anchor(id);
      if (!a) continue;
      for (uint32_t v = 0; v < cx.num_vertices(); ++v) {
        if (cx.vertex_side(v, (*a)[0]) || cx.vertex_side(v, (*a)[1]) || cx.vertex_side(v, (*a)[2])) continue;
        EXPECT_EQ(cx.vertex_side(v, id), 0) << "anchored plane " << id;
        ++corners;
      }
    }
    EXPECT_GT(corners, 0u);
  }
}

}  // namespace
}  // namespace mc
