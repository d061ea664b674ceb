// The exact inside volume of a convex cell by columns (core/column_volume.hpp, docs/design.md
// "Inside volume by columns"): polytope clipping, and the inside volume of cells against a gable
// house whose answers are known in closed form, with cells sharing its faces, its ridge line in
// plan, rotated and far from the origin, and the surface oriented either way.
#include "core/column_volume.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace mc {
namespace {

// An axis-aligned box as a polytope, faces counter-clockwise seen from outside.
ConvexPolytope box(const Vec3& lo, const Vec3& hi) {
  auto v = [&](int i) { return Vec3{i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z}; };
  const int f[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  ConvexPolytope p;
  for (const auto& q : f) {
    for (int i : q) p.points.push_back(v(i));
    p.close_face();
  }
  return p;
}

BBox box_of(const ConvexPolytope& p) {
  BBox b;
  for (const Vec3& v : p.points) b.add(v);
  return b;
}

// A gable house: footprint [0,10]×[0,6], eaves at 4 m, ridge along x at y = 3, 7 m; 330 m³.
TriangleSoup gable() {
  TriangleSoup s;
  s.vertices = {{0, 0, 0},  {10, 0, 0}, {10, 6, 0}, {0, 6, 0}, {0, 0, 4},
                {10, 0, 4}, {10, 6, 4}, {0, 6, 4},  {0, 3, 7}, {10, 3, 7}};
  const std::vector<std::vector<uint32_t>> faces = {
      {0, 3, 2, 1}, {0, 1, 5, 4}, {2, 3, 7, 6}, {4, 5, 9, 8}, {6, 7, 8, 9}, {0, 4, 8, 7, 3}, {1, 2, 6, 9, 5}};
  for (const auto& f : faces)
    for (size_t i = 1; i + 1 < f.size(); ++i) s.triangles.push_back({f[0], f[i], f[i + 1]});
  s.source_face.assign(s.triangles.size(), 0);
  return s;
}

TriangleSoup transformed(TriangleSoup s, const std::function<Vec3(const Vec3&)>& f) {
  for (Vec3& v : s.vertices) v = f(v);
  return s;
}

ConvexPolytope transformed(ConvexPolytope p, const std::function<Vec3(const Vec3&)>& f) {
  for (Vec3& v : p.points) v = f(v);
  return p;
}

double inside(const ColumnVolume& cv, const ConvexPolytope& cell) { return cv.inside(cell, box_of(cell)); }

ConvexPolytope clip(const ConvexPolytope& p, const Plane& keep_below) {
  ConvexPolytope out;
  clip_polytope(p, keep_below, 1e-12, out);
  return out;
}

TEST(ConvexPolytope, VolumeAndClipByAPlane) {
  const ConvexPolytope cube = box({0, 0, 0}, {1, 1, 1});
  EXPECT_NEAR(polytope_volume(cube), 1.0, 1e-12);
  // x + y + z <= 1.5 halves the unit cube (central symmetry).
  const Vec3 n = normalized(Vec3{1, 1, 1});
  const ConvexPolytope half = clip(cube, {n, -1.5 / std::sqrt(3.0)});
  EXPECT_NEAR(polytope_volume(half), 0.5, 1e-12);
  // A corner tetrahedron: x + y + z <= 1 keeps 1/6.
  EXPECT_NEAR(polytope_volume(clip(cube, {n, -1 / std::sqrt(3.0)})), 1.0 / 6, 1e-12);
  // A plane along a face keeps everything (no second face on it), one beyond keeps nothing.
  EXPECT_NEAR(polytope_volume(clip(cube, {{0, 0, 1}, -1})), 1.0, 1e-12);
  EXPECT_TRUE(clip(cube, {{0, 0, 1}, 0}).empty());
  EXPECT_TRUE(clip(cube, {{0, 0, 1}, 0.5}).empty());
  // Through a vertex and a face's diagonal: x + y <= 1 keeps half, closed by one new face.
  const ConvexPolytope wedge = clip(cube, {normalized(Vec3{1, 1, 0}), -1 / std::sqrt(2.0)});
  EXPECT_NEAR(polytope_volume(wedge), 0.5, 1e-12);
  EXPECT_EQ(wedge.face_count(), 5u);
}

TEST(ColumnVolume, GableHouseCellsKnownInClosedForm) {
  const ColumnVolume cv(gable());
  EXPECT_NEAR(inside(cv, box({-1, -1, -1}, {11, 7, 9})), 330, 1e-9);
  EXPECT_NEAR(inside(cv, box({0, 0, 0}, {10, 3, 10})), 165, 1e-9);   // half along the ridge line
  EXPECT_NEAR(inside(cv, box({-1, -1, 5}, {11, 7, 10})), 40, 1e-9);  // the roof above 5 m
  EXPECT_NEAR(inside(cv, box({0, 0, 5}, {10, 3, 10})), 20, 1e-9);    // its half: ridge on a facet
  EXPECT_NEAR(inside(cv, box({2, 1, 1}, {3, 2, 2})), 1, 1e-12);      // deep inside
}

TEST(ColumnVolume, CellsSharingTheSurfacesFacesAreExact) {
  const ColumnVolume cv(gable());
  EXPECT_NEAR(inside(cv, box({0, 0, 0}, {10, 6, 4})), 240, 1e-9);   // walls: every facet on a face or eave
  EXPECT_NEAR(inside(cv, box({0, 0, -3}, {10, 6, 0})), 0, 1e-9);    // under the ground face
  EXPECT_NEAR(inside(cv, box({2, -2, 0}, {4, 0, 4})), 0, 1e-9);     // against a wall outside
  EXPECT_NEAR(inside(cv, box({-5, -5, 7}, {15, 15, 9})), 0, 1e-9);  // on the ridge's height
}

TEST(ColumnVolume, MoreColumnsThanTheLimitAreNotMeasured) {
  // The gable's 6 triangles that face up or down (ground and roofs; the walls face sideways)
  // stand over the whole house: a cell over all of them has 6 terms, one over the roof's half 4
  // or fewer.
  const ColumnVolume cv(gable());
  const ConvexPolytope all = box({-1, -1, -1}, {11, 7, 9});
  EXPECT_EQ(cv.columns_over(box_of(all)), 6u);
  EXPECT_NEAR(cv.inside(all, box_of(all), 6), 330, 1e-9);
  EXPECT_EQ(cv.inside(all, box_of(all), 5), -1);
  EXPECT_EQ(cv.inside(all, box_of(all), 1), -1);
  const ConvexPolytope half = box({0, 0, 5}, {10, 3, 10});
  EXPECT_LE(cv.columns_over(box_of(half)), 4u);
  EXPECT_NEAR(cv.inside(half, box_of(half), 4), 20, 1e-9);
}

TEST(ColumnVolume, OrientationOfTheSurfaceDoesNotMatter) {
  TriangleSoup in = gable();
  for (auto& t : in.triangles) std::swap(t[1], t[2]);
  const ColumnVolume cv(in);
  EXPECT_NEAR(inside(cv, box({-1, -1, 5}, {11, 7, 10})), 40, 1e-9);
  EXPECT_NEAR(inside(cv, box({0, 0, 0}, {10, 3, 10})), 165, 1e-9);
}

TEST(ColumnVolume, RotatedAndFarFromTheOriginAsInTheLocalFrame) {
  // A rotation with no axis along x, y or z (walls and roofs inclined in the frame), 1e5 m out.
  const double a = 0.7, b = 0.4;
  const Vec3 t{1e5, -2e5, 35};
  auto f = [&](const Vec3& p) {
    const Vec3 r1{p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a), p.z};
    return Vec3{r1.x, r1.y * std::cos(b) - r1.z * std::sin(b), r1.y * std::sin(b) + r1.z * std::cos(b)} + t;
  };
  const ColumnVolume cv(transformed(gable(), f));
  EXPECT_NEAR(inside(cv, transformed(box({0, 0, 0}, {10, 3, 10}), f)), 165, 1e-6);
  EXPECT_NEAR(inside(cv, transformed(box({-1, -1, 5}, {11, 7, 10}), f)), 40, 1e-6);
  EXPECT_NEAR(inside(cv, transformed(box({0, 0, 0}, {10, 6, 4}), f)), 240, 1e-6);
  EXPECT_NEAR(inside(cv, transformed(box({2, -2, 0}, {4, 0, 4}), f)), 0, 1e-6);
}

}  // namespace
}  // namespace mc
