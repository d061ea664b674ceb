// check_solid and common_volume on hand-made shells: one for every error code they report.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>

#include "core/geometry.hpp"
#include "core/solid_validation.hpp"

namespace mc {
namespace {

using Rings = std::vector<std::vector<uint32_t>>;

PolygonMesh mesh(std::vector<Vec3> v, const std::vector<Rings>& faces) {
  PolygonMesh m;
  m.vertices = std::move(v);
  for (const auto& f : faces) m.faces.push_back({f, -1});
  return m;
}

// Axis-aligned box, faces counter-clockwise seen from outside.
PolygonMesh box(Vec3 lo, Vec3 hi) {
  return mesh(
      {{lo.x, lo.y, lo.z},
       {hi.x, lo.y, lo.z},
       {hi.x, hi.y, lo.z},
       {lo.x, hi.y, lo.z},
       {lo.x, lo.y, hi.z},
       {hi.x, lo.y, hi.z},
       {hi.x, hi.y, hi.z},
       {lo.x, hi.y, hi.z}},
      {{{0, 3, 2, 1}}, {{4, 5, 6, 7}}, {{0, 1, 5, 4}}, {{2, 3, 7, 6}}, {{0, 4, 7, 3}}, {{1, 2, 6, 5}}});
}

PolygonMesh unit_cube() { return box({0, 0, 0}, {1, 1, 1}); }

// Two shells as one mesh (vertices are merged by coordinates in check_solid).
PolygonMesh merged(const PolygonMesh& a, const PolygonMesh& b) {
  PolygonMesh m = a;
  const uint32_t base = static_cast<uint32_t>(a.vertices.size());
  m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (Polygon f : b.faces) {
    for (auto& r : f.rings)
      for (auto& v : r) v += base;
    m.faces.push_back(f);
  }
  return m;
}

std::vector<int> codes(const SolidCheck& c) {
  std::vector<int> out;
  for (const auto& e : c.errors) out.push_back(e.code);
  return out;
}

bool has(const SolidCheck& c, int code) {
  const auto v = codes(c);
  return std::find(v.begin(), v.end(), code) != v.end();
}

std::string describe(const SolidCheck& c) {
  std::string s;
  for (const auto& e : c.errors) s += std::to_string(e.code) + " " + e.name + ": " + e.message + "\n";
  return s;
}

TEST(SolidValidation, UnitCubeIsValid) {
  const SolidCheck c = check_solid(unit_cube());
  EXPECT_TRUE(c.valid()) << describe(c);
  EXPECT_TRUE(c.closed_manifold);
  EXPECT_NEAR(c.volume, 1.0, 1e-12);
  EXPECT_NEAR(c.area, 6.0, 1e-12);
  EXPECT_NEAR(c.hull_volume, 1.0, 1e-9);
  EXPECT_NEAR(c.convexity, 1.0, 1e-9);
  EXPECT_EQ(c.shell.triangles.size(), 12u);
}

TEST(SolidValidation, CityCoordinatesKeepTheirPrecision) {
  const SolidCheck c = check_solid(box({85012.125, 446210.5, -2.0}, {85022.125, 446216.5, 7.5}));
  EXPECT_TRUE(c.valid()) << describe(c);
  EXPECT_NEAR(c.volume, 10 * 6 * 9.5, 1e-6);
}

TEST(SolidValidation, FrameWithAHoleThroughIt) {
  // A unit square frame around a 0.5 x 0.5 hole: the top and bottom faces have inner rings.
  std::vector<Vec3> v;
  for (double z : {0.0, 1.0}) {
    for (auto [x, y] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}) v.push_back({x, y, z});
    for (auto [x, y] : {std::pair{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}})
      v.push_back({x, y, z});
  }
  // Bottom: outer 0-3, inner 4-7; top: outer 8-11, inner 12-15.
  const SolidCheck c = check_solid(mesh(v, {{{0, 3, 2, 1}, {4, 5, 6, 7}},
                                            {{8, 9, 10, 11}, {12, 15, 14, 13}},
                                            {{0, 1, 9, 8}},
                                            {{2, 3, 11, 10}},
                                            {{0, 8, 11, 3}},
                                            {{1, 2, 10, 9}},
                                            {{4, 7, 15, 12}},
                                            {{5, 13, 14, 6}},
                                            {{5, 4, 12, 13}},
                                            {{7, 6, 14, 15}}}));
  EXPECT_TRUE(c.valid()) << describe(c);
  EXPECT_NEAR(c.volume, 0.75, 1e-12);
  EXPECT_NEAR(c.convexity, 0.75, 1e-9);
}

TEST(SolidValidation, MissingFaceIsNotClosed) {
  PolygonMesh m = unit_cube();
  m.faces.pop_back();
  const SolidCheck c = check_solid(m);
  EXPECT_TRUE(has(c, 302)) << describe(c);
  EXPECT_FALSE(c.closed_manifold);
  EXPECT_EQ(c.errors[0].name, "SHELL_NOT_CLOSED");
}

TEST(SolidValidation, InwardFacesAreWronglyOriented) {
  PolygonMesh m = unit_cube();
  for (auto& f : m.faces) std::reverse(f.rings[0].begin(), f.rings[0].end());
  const SolidCheck c = check_solid(m);
  EXPECT_EQ(codes(c), std::vector<int>{405}) << describe(c);
  EXPECT_EQ(c.errors[0].name, "WRONG_ORIENTATION_SHELL");
  EXPECT_NEAR(c.volume, -1.0, 1e-12);
  EXPECT_FALSE(c.closed_manifold);
}

TEST(SolidValidation, OneFlippedFace) {
  // The top face's triangles go in first; the sides that meet them in the same direction do not
  // fit, reversed (307) or not at all (303), as their triangles come.
  PolygonMesh m = unit_cube();
  std::reverse(m.faces[1].rings[0].begin(), m.faces[1].rings[0].end());
  const SolidCheck c = check_solid(m);
  ASSERT_FALSE(c.valid());
  for (int code : codes(c)) EXPECT_TRUE(code == 303 || code == 307) << describe(c);
}

TEST(SolidValidation, ShellThroughItself) {
  // The cube as triangles, one corner pushed through the opposite corner: closed, 2-manifold,
  // every face planar, but its faces cross.
  const PolygonMesh q = unit_cube();
  PolygonMesh m;
  m.vertices = q.vertices;
  for (const auto& f : q.faces) {
    const auto& r = f.rings[0];
    m.faces.push_back({{{r[0], r[1], r[2]}}, -1});
    m.faces.push_back({{{r[0], r[2], r[3]}}, -1});
  }
  m.vertices[6] = {-0.5, -0.4, -0.3};
  const SolidCheck c = check_solid(m);
  EXPECT_TRUE(has(c, 306)) << describe(c);
  EXPECT_FALSE(c.closed_manifold);
}

TEST(SolidValidation, BowTieRing) {
  PolygonMesh m = unit_cube();
  m.faces[1].rings[0] = {4, 6, 5, 7};  // the top face's diagonals as edges
  const SolidCheck c = check_solid(m);
  EXPECT_TRUE(has(c, 104)) << describe(c);
}

TEST(SolidValidation, NonPlanarQuadBeyondTheToleranceOnly) {
  PolygonMesh m = unit_cube();
  m.vertices[6].z += 0.01;  // only the top face bends (the move is in the planes of the sides)
  SolidCheck c = check_solid(m);
  EXPECT_EQ(codes(c), std::vector<int>{203}) << describe(c);
  EXPECT_NE(c.errors[0].message.find("face 1: a point lies 0.0025 m"), std::string::npos)
      << c.errors[0].message;
  EXPECT_TRUE(c.closed_manifold);  // the shell checks still ran
  m.vertices[6].z = 1.0008;        // 0.2 mm off the plane
  c = check_solid(m);
  EXPECT_TRUE(c.valid()) << describe(c);
  EXPECT_FALSE(check_solid(m, {1e-6, 1e-4}).valid());
}

TEST(SolidValidation, CubesSharingAnEdgeOrAVertexAreNotManifold) {
  const SolidCheck edge = check_solid(merged(unit_cube(), box({1, 1, 0}, {2, 2, 1})));
  EXPECT_EQ(codes(edge), std::vector<int>{303}) << describe(edge);
  EXPECT_NE(edge.errors[0].message.find("face 6 would make an edge shared by more than two faces"),
            std::string::npos)
      << describe(edge);
  const SolidCheck vertex = check_solid(merged(unit_cube(), box({1, 1, 1}, {2, 2, 2})));
  EXPECT_EQ(codes(vertex), std::vector<int>{303}) << describe(vertex);
  const SolidCheck apart = check_solid(merged(unit_cube(), box({3, 0, 0}, {4, 1, 1})));
  EXPECT_EQ(codes(apart), std::vector<int>{305}) << describe(apart);
}

TEST(SolidValidation, DuplicateConsecutivePointsAndTooFewPoints) {
  PolygonMesh m = unit_cube();
  m.faces[0].rings[0] = {0, 3, 3, 2, 1};
  EXPECT_EQ(codes(check_solid(m)), std::vector<int>{102});
  m.vertices.push_back({0, 1, 0.0000001});  // a copy of vertex 3 within the snap tolerance
  m.faces[0].rings[0] = {0, 3, 8, 2, 1};
  EXPECT_EQ(codes(check_solid(m)), std::vector<int>{102});
  m.faces[0].rings[0] = {0, 3};
  const SolidCheck c = check_solid(m);
  EXPECT_TRUE(has(c, 101)) << describe(c);
  EXPECT_TRUE(has(c, 302)) << describe(c);  // the face is gone: a hole in the shell
}

TEST(SolidValidation, CommonVolumeTouchingOverlappingIdentical) {
  const SolidCheck a = check_solid(unit_cube());
  const SolidCheck touching = check_solid(box({1, 0, 0}, {2, 1, 1}));
  const SolidCheck half = check_solid(box({0.5, 0, 0}, {1.5, 1, 1}));
  const SolidCheck inside = check_solid(box({0.25, 0.25, 0.25}, {0.75, 0.75, 0.75}));
  ASSERT_TRUE(a.valid() && touching.valid() && half.valid() && inside.valid());
  EXPECT_NEAR(common_volume(a.shell, touching.shell).value().volume, 0.0, 1e-12);
  EXPECT_NEAR(common_volume(a.shell, half.shell).value().volume, 0.5, 1e-9);
  EXPECT_NEAR(common_volume(a.shell, half.shell).value().area, 4.0, 1e-9);
  EXPECT_NEAR(common_volume(a.shell, a.shell).value().volume, 1.0, 1e-9);
  EXPECT_NEAR(common_volume(a.shell, inside.shell).value().volume, 0.125, 1e-9);
  // The fallback agrees, shared faces included.
  EXPECT_NEAR(common_volume_by_faces(a.shell, touching.shell).value().volume, 0.0, 1e-12);
  EXPECT_NEAR(common_volume_by_faces(a.shell, half.shell).value().volume, 0.5, 1e-9);
  EXPECT_NEAR(common_volume_by_faces(a.shell, half.shell).value().area, 4.0, 1e-9);
  EXPECT_NEAR(common_volume_by_faces(a.shell, a.shell).value().volume, 1.0, 1e-9);
  EXPECT_NEAR(common_volume_by_faces(a.shell, inside.shell).value().volume, 0.125, 1e-9);
  EXPECT_NEAR(common_volume_by_faces(inside.shell, a.shell).value().volume, 0.125, 1e-9);
  // A shell that is not a 2-manifold cannot be corefined: no number rather than a guess.
  EXPECT_FALSE(common_volume(
      a.shell, check_solid(merged(box({0, 0, 0}, {1, 1, 1}), box({1, 1, 0}, {2, 2, 1}))).shell));
}

// Hand-made parts on which val3dity 2.6.0 and check_solid once disagreed (tools/val3dity/
// crosscheck.py, docs/reliability.md): coordinates on a grid of `scale` m as a CityJSON file holds
// them (integer * scale + translate, as val3dity computes them), the expected codes val3dity's own.
using GridPoint = std::array<int64_t, 3>;
using GridFace = std::vector<std::vector<GridPoint>>;

PolygonMesh grid_mesh(const std::vector<GridFace>& faces, const Vec3& translate, double scale = 0.001) {
  PolygonMesh m;
  std::map<GridPoint, uint32_t> index;  // vertices in order of first use, as the validators read them
  for (const GridFace& f : faces) {
    Polygon poly;
    for (const auto& ring : f) {
      std::vector<uint32_t> r;
      for (const GridPoint& g : ring) {
        auto [it, fresh] = index.try_emplace(g, static_cast<uint32_t>(m.vertices.size()));
        if (fresh)
          m.vertices.push_back({static_cast<double>(g[0]) * scale + translate.x,
                                static_cast<double>(g[1]) * scale + translate.y,
                                static_cast<double>(g[2]) * scale + translate.z});
        r.push_back(it->second);
      }
      poly.rings.push_back(std::move(r));
    }
    m.faces.push_back(std::move(poly));
  }
  return m;
}

// An axis-aligned box (bottom, top, -y, +x, +y, -x), outward.
std::vector<GridFace> grid_box(GridPoint lo, GridPoint hi) {
  const auto p = [&](int i, int j, int k) {
    return GridPoint{i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]};
  };
  return {
      {{p(0, 0, 0), p(0, 1, 0), p(1, 1, 0), p(1, 0, 0)}}, {{p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1)}},
      {{p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1)}}, {{p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1)}},
      {{p(1, 1, 0), p(0, 1, 0), p(0, 1, 1), p(1, 1, 1)}}, {{p(0, 1, 0), p(0, 0, 0), p(0, 0, 1), p(0, 1, 1)}}};
}

// The faces of a pit below a hole of a top face: one triangle from each hole edge to an apex
// `depth` below the hole's centre.
std::vector<GridFace> pyramid_pit(const std::vector<GridPoint>& hole, int64_t depth) {
  GridPoint c{0, 0, hole[0][2] - depth};
  for (const auto& h : hole) c[0] += h[0], c[1] += h[1];
  c[0] /= static_cast<int64_t>(hole.size()), c[1] /= static_cast<int64_t>(hole.size());
  std::vector<GridFace> out;
  for (size_t i = 0; i < hole.size(); ++i) out.push_back({{hole[(i + 1) % hole.size()], hole[i], c}});
  return out;
}

const Vec3 kLambert93{652417.613, 6862291.337, 35.21};  // where a French CityGML file's parts lie
constexpr int64_t S = 10000;                            // 10 m at a 1 mm grid

std::vector<int> val3dity_codes(const PolygonMesh& m) {
  return codes(check_solid(m, val3dity_exact_tolerances()));
}

TEST(SolidValidation, VerticesOneGridStepApartAreMergedAsTheCoordinatesRound) {
  // The top face's corner 1 mm off the sides' corner: val3dity merges the two when their squared
  // distance, computed from the file's coordinates, is below 1e-6, which exactly 1 mm is or not
  // as the coordinates round. Its 302 ("Location hole") was on such a part, which the old merge
  // test (distance <= 1 mm) called closed.
  std::vector<GridFace> f = grid_box({0, 0, 0}, {S, S, S});
  f[1] = {{{0, 0, S}, {S + 1, 0, S}, {S, S, S}, {0, S, S}}};
  EXPECT_EQ(val3dity_codes(grid_mesh(f, kLambert93)), std::vector<int>{302});
  EXPECT_EQ(val3dity_codes(grid_mesh(f, {0, 0, 0})), std::vector<int>{});  // rounds below 1 mm
  // The writer cannot know how the file's coordinates will round: either way is invalid for it.
  for (const Vec3& t : {kLambert93, Vec3{0, 0, 0}}) {
    const SolidCheck c = check_solid(grid_mesh(f, t), val3dity_tolerances());
    EXPECT_EQ(codes(c), std::vector<int>{302}) << describe(c);
  }
  // 0.9 mm is one vertex and 1.1 mm two, for both.
  for (const auto& [off, want] : {std::pair{9, std::vector<int>{}}, std::pair{11, std::vector<int>{302}}}) {
    std::vector<GridFace> g = grid_box({0, 0, 0}, {10 * S, 10 * S, 10 * S});
    g[1] = {{{0, 0, 10 * S}, {10 * S + off, 0, 10 * S}, {10 * S, 10 * S, 10 * S}, {0, 10 * S, 10 * S}}};
    EXPECT_EQ(val3dity_codes(grid_mesh(g, kLambert93, 0.0001)), want) << off;
    EXPECT_EQ(codes(check_solid(grid_mesh(g, kLambert93, 0.0001), val3dity_tolerances())), want) << off;
  }
}

TEST(SolidValidation, AVertexMergesIntoTheEarliestCloseOne) {
  // p is within the snap distance of two merged vertices 1.8 mm apart: val3dity takes the first
  // in its list, whichever side it lies on.
  for (const double first : {0.0009, -0.0009}) {
    std::vector<Vec3> merged;
    const auto id = merge_vertices({{first, 0, 0}, {-first, 0, 0}, {0, 0, 0}}, 0.001, merged, true);
    EXPECT_EQ(id, (std::vector<uint32_t>{0, 1, 0})) << first;
  }
}

TEST(SolidValidation, HoleCornerOnTheOuterRingsEdgeLeavesTheShellOpen) {
  // The top face's hole touches the middle of its outer ring's edge at (4, 0): the face's
  // triangles split that edge, the wall below does not, and val3dity's shell has a hole there.
  std::vector<GridFace> f = grid_box({0, 0, 0}, {S, S, S});
  const std::vector<GridPoint> hole{{4000, 0, S}, {2000, 2000, S}, {4000, 4000, S}, {6000, 2000, S}};
  f[1].push_back(hole);
  for (auto& pit : pyramid_pit(hole, 3000)) f.push_back(pit);
  EXPECT_EQ(val3dity_codes(grid_mesh(f, kLambert93)), std::vector<int>{302});
}

TEST(SolidValidation, FacesWithHolesFollowGeosRules) {
  // Outer ring with vertices at x = 4 m on both long edges; walls carry them too.
  std::vector<GridFace> walls = grid_box({0, 0, 0}, {S, S, S});
  walls[2] = {{{0, 0, 0}, {S, 0, 0}, {S, 0, S}, {4000, 0, S}, {0, 0, S}}};
  walls[4] = {{{S, S, 0}, {0, S, 0}, {0, S, S}, {4000, S, S}, {S, S, S}}};
  const std::vector<GridPoint> outer{{0, 0, S}, {4000, 0, S}, {S, 0, S}, {S, S, S}, {4000, S, S}, {0, S, S}};
  // A hole touching the outer ring at two vertices cuts the face in two (205); the shell is fine.
  const std::vector<GridPoint> diamond{{4000, 0, S}, {2000, S / 2, S}, {4000, S, S}, {6000, S / 2, S}};
  std::vector<GridFace> f = walls;
  f[1] = {outer, diamond};
  for (auto& pit : pyramid_pit(diamond, 3000)) f.push_back(pit);
  EXPECT_EQ(val3dity_codes(grid_mesh(f, kLambert93)), std::vector<int>{205});
  // A hole beside the face (206), one inside another (207), the same hole twice (201).
  const std::vector<GridPoint> beside{
      {S + 2000, 2000, S}, {S + 2000, 6000, S}, {S + 6000, 6000, S}, {S + 6000, 2000, S}};
  const std::vector<GridPoint> h1{{1000, 1000, S}, {1000, 8000, S}, {8000, 8000, S}, {8000, 1000, S}};
  const std::vector<GridPoint> h2{{3000, 3000, S}, {3000, 5000, S}, {5000, 5000, S}, {5000, 3000, S}};
  using Holes = std::vector<std::vector<GridPoint>>;
  for (const auto& [holes, code] :
       {std::pair{Holes{beside}, 206}, std::pair{Holes{h1, h2}, 207}, std::pair{Holes{h2, h2}, 201}}) {
    std::vector<GridFace> g = grid_box({0, 0, 0}, {S, S, S});
    for (const auto& h : holes) g[1].push_back(h);
    const std::vector<int> c = val3dity_codes(grid_mesh(g, kLambert93));
    ASSERT_FALSE(c.empty()) << code;
    EXPECT_EQ(c.front(), code);  // (the shell checks that val3dity never reaches come after)
  }
}

TEST(SolidValidation, ARepeatedVertexIsConsecutivePointsOnly) {
  // A 4-point ring of two distinct points: val3dity's 102 (its 101 counts the ring's points).
  std::vector<GridFace> f = grid_box({0, 0, 0}, {S, S, S});
  f.push_back({{{S, 0, 0}, {S, 0, S}, {S, 0, S}, {S, 0, 0}}});
  const PolygonMesh m = grid_mesh(f, kLambert93);
  EXPECT_EQ(val3dity_codes(m), std::vector<int>{102});
}

TEST(SolidValidation, FlippedFaceAsVal3dityBuildsTheShell) {
  // The top face reversed: its triangles go in second, after the bottom's; of the sides, the ones
  // whose reversed triangles fit are 307, the others 303 (val3dity: 307 on faces 2 and 3, 303 on
  // faces 4 and 5).
  std::vector<GridFace> f = grid_box({0, 0, 0}, {S, S, S});
  std::reverse(f[1][0].begin(), f[1][0].end());
  const SolidCheck c = check_solid(grid_mesh(f, kLambert93), val3dity_exact_tolerances());
  EXPECT_EQ(codes(c), (std::vector<int>{303, 307})) << describe(c);
}

TEST(SolidValidation, InteriorsOverlapExactly) {
  const SolidCheck a = check_solid(grid_mesh(grid_box({0, 0, 0}, {S, S, S}), kLambert93));
  const SolidCheck touching = check_solid(grid_mesh(grid_box({S, 0, 0}, {2 * S, S, S}), kLambert93));
  // 1 mm x 1 m x 1 m = 0.001 m³ in common: below any volume tolerance, an overlap for val3dity.
  const SolidCheck sliver =
      check_solid(grid_mesh(grid_box({S - 1, 0, 0}, {S + 1000, 1000, 1000}), kLambert93));
  const SolidCheck corner = check_solid(grid_mesh(grid_box({S, S, S}, {2 * S, 2 * S, 2 * S}), kLambert93));
  ASSERT_TRUE(a.valid() && touching.valid() && sliver.valid() && corner.valid());
  EXPECT_FALSE(interiors_overlap(a.shell, touching.shell));
  EXPECT_FALSE(interiors_overlap(a.shell, corner.shell));
  EXPECT_TRUE(interiors_overlap(a.shell, sliver.shell));
  EXPECT_TRUE(interiors_overlap(sliver.shell, a.shell));
  EXPECT_TRUE(interiors_overlap(a.shell, a.shell));
}

// The full scan min_distance_beyond stands for: every point of `a` not a point of `b` against
// every triangle of `b`.
bool beyond_by_full_scan(const TriangleShell& a, const TriangleShell& b, double d) {
  for (const Vec3& p : a.points) {
    if (std::find(b.points.begin(), b.points.end(), p) != b.points.end()) continue;
    for (const auto& t : b.triangles) {
      const Vec3 q = p - closest_on_triangle(p, b.points[t[0]], b.points[t[1]], b.points[t[2]]);
      if (dot(q, q) <= d * d) return false;
    }
  }
  return true;
}

TEST(SolidValidation, MinDistanceBeyondAnswersAsTheFullScan) {
  // Boxes side by side, apart by 0 (touching: the shared corners are left out), by less than,
  // exactly and more than the distance, and overlapping; far from the origin as a tile is.
  const Vec3 far{85000, 446000, 0};
  const double d = 0.002;
  const SolidCheck a = check_solid(box(far + Vec3{0, 0, 0}, far + Vec3{4, 3, 5}));
  ASSERT_TRUE(a.valid());
  int near_cases = 0;
  for (const double gap : {0.0, 0.001, 0.002, 0.0021, 0.5, -0.3})
    for (const double dz : {0.0, 0.7}) {
      SCOPED_TRACE(testing::Message() << "gap " << gap << " dz " << dz);
      const SolidCheck b = check_solid(box(far + Vec3{4 + gap, 1, dz}, far + Vec3{7, 2.5, 3 + dz}));
      ASSERT_TRUE(b.valid());
      for (const double dist : {d, 0.01}) {
        EXPECT_EQ(min_distance_beyond(a.shell, b.shell, dist), beyond_by_full_scan(a.shell, b.shell, dist));
        const bool expected = beyond_by_full_scan(b.shell, a.shell, dist);  // b's corners near a's face
        EXPECT_EQ(min_distance_beyond(b.shell, a.shell, dist), expected);
        near_cases += !expected;
      }
    }
  EXPECT_GT(near_cases, 4);  // the scan does find points within the distance
  TriangleShell empty;
  EXPECT_TRUE(min_distance_beyond(a.shell, empty, d));
}

// Twice the area over the longest edge squared: the triangle's height relative to that edge.
double fatness(const std::vector<Vec3>& p, const std::array<uint32_t, 3>& t) {
  const Vec3 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
  const double l = std::max({dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)});
  return norm(cross(b - a, c - a)) / l;
}

TEST(SolidValidation, CanonicalTriangulationFlipsAThinQuadsThinnerEarOnce) {
  // A shared wall on a 1 cm grid (a tile building turned and moved to 6.4e6, then snapped; the
  // points in the order of their ids in the level's vertex pool): its top edge runs 4 -> 5 -> 2,
  // with 5 a hair below the line 4-2 and 14 cm from 2. Either diagonal makes an ear within 1/100
  // of its chord: 5 over 4-2 (1.7 mm over 13 m) or 2 over 5-0 (14 cm over 15.6 m). Flipping each
  // in turn would go back and forth and could end on the first, a sliver whose fold makes the
  // part's shell intersect itself (306).
  const Vec3 o{6418800, 6606200, 0};
  const std::vector<Vec3> p = {o + Vec3{40.65, 10.96, 0.00},  o + Vec3{27.57, 9.88, 0.00},
                               o + Vec3{40.65, 10.97, 15.63}, o + Vec3{27.57, 9.89, 15.56},
                               o + Vec3{27.65, 9.90, 15.56},  o + Vec3{40.51, 10.96, 15.63}};
  auto sorted = [](std::vector<std::array<uint32_t, 3>> tris) {
    for (auto& t : tris) std::sort(t.begin(), t.end());
    std::sort(tris.begin(), tris.end());
    return tris;
  };
  std::vector<std::array<uint32_t, 3>> tris, reversed;
  ASSERT_TRUE(triangulate_polygon_canonical({{0, 1, 3, 4, 5, 2}}, p, tris));
  ASSERT_TRUE(triangulate_polygon_canonical({{2, 5, 4, 3, 1, 0}}, p, reversed));
  ASSERT_EQ(tris.size(), 4u);
  for (const auto& t : tris) EXPECT_GT(fatness(p, t), 1e-3) << t[0] << " " << t[1] << " " << t[2];
  EXPECT_EQ(sorted(tris), sorted(reversed));  // the face's twin in the neighbour gets the same
}

}  // namespace
}  // namespace mc
