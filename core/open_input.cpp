#include "core/open_input.hpp"

#include "core/solid_validation.hpp"  // triangulate_polygon
#include "core/thread_tag.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

namespace mc {

namespace {

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return norm(p - (a + ab * t));
}

}  // namespace

OpenInput analyse_open_input(const PolygonMesh& mesh, double dist) {
  OpenInput out;
  double lowest = 1e300;
  for (const Vec3& v : mesh.vertices) lowest = std::min(lowest, v.z);
  std::map<std::pair<uint32_t, uint32_t>, int> uses;
  for (const Polygon& f : mesh.faces)
    for (const auto& r : f.rings)
      for (size_t i = 0; i < r.size(); ++i) {
        const uint32_t a = r[i], b = r[(i + 1) % r.size()];
        if (a != b) ++uses[{std::min(a, b), std::max(a, b)}];
      }
  std::vector<std::pair<Vec3, Vec3>> edges;
  for (const auto& [e, n] : uses) {
    if (n == 1) edges.emplace_back(mesh.vertices[e.first], mesh.vertices[e.second]);
    if (n > 2) ++out.nonmanifold_edges;
  }
  // Coverage by other boundary edges: an edge is covered at a sample point by a nearly parallel
  // boundary edge within δ. Each edge's candidates are the parallel ones whose boxes come within
  // δ of its own (a box farther than δ on some axis holds no point within δ), found once for its
  // four samples; the edges are tested in parallel and summed in order.
  struct Edge {
    Vec3 e;
    double length;
    BBox box;
  };
  std::vector<Edge> info(edges.size());
  for (size_t j = 0; j < edges.size(); ++j) {
    info[j].e = edges[j].second - edges[j].first;
    info[j].length = norm(info[j].e);
    info[j].box.add(edges[j].first);
    info[j].box.add(edges[j].second);
  }
  // A margin for the rounding of the sample points (coordinates may be georeferenced): the exact
  // test below decides, the filter only has to keep every edge that might pass it.
  double magnitude = 0;
  for (const Vec3& v : mesh.vertices)
    magnitude = std::max({magnitude, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  const double reach = dist * (1 + 1e-6) + 1e-9 * magnitude;
  auto far_apart = [&](const BBox& p, const BBox& q) {
    return p.lo.x - q.hi.x > reach || q.lo.x - p.hi.x > reach || p.lo.y - q.hi.y > reach ||
           q.lo.y - p.hi.y > reach || p.lo.z - q.hi.z > reach || q.lo.z - p.hi.z > reach;
  };
  std::vector<int> uncovered(edges.size(), 0);
  tbb::parallel_for(
      size_t(0), edges.size(), with_thread_tag([&](size_t i) {
        const auto& [a, b] = edges[i];
        const double len = info[i].length;
        if (len <= 0) return;
        const Vec3 d = (b - a) * (1.0 / len);
        std::vector<uint32_t> near;
        for (size_t j = 0; j < edges.size(); ++j) {
          if (j == i || info[j].length <= 0 || std::abs(dot(info[j].e, d)) < 0.99 * info[j].length) continue;
          if (!far_apart(info[i].box, info[j].box)) near.push_back(static_cast<uint32_t>(j));
        }
        for (int s = 0; s < 4; ++s) {
          const Vec3 p = a + (b - a) * ((2 * s + 1) / 8.0);
          bool covered = false;
          for (size_t k = 0; k < near.size() && !covered; ++k)
            covered = point_segment_distance(p, edges[near[k]].first, edges[near[k]].second) <= dist;
          uncovered[i] += !covered;
        }
      }));
  for (size_t i = 0; i < edges.size(); ++i) {
    const auto& [a, b] = edges[i];
    const double len = info[i].length;
    out.boundary_length += len;
    if (len <= 0 || !uncovered[i]) continue;
    if (std::max(a.z, b.z) > lowest + dist) out.uncovered_length += len * uncovered[i] / 4.0;
    out.uncovered_edges.push_back(edges[i]);
  }
  // Ground: semantic, else a downward horizontal face at the lowest level.
  bool& semantics = out.semantics;
  for (const Polygon& f : mesh.faces) {
    if (f.semantic >= 0) semantics = true;
    if (mesh.is_label(f.semantic, "GroundSurface")) out.has_ground = true;
  }
  if (!semantics)
    for (const Polygon& f : mesh.faces) {
      const FaceGeometry g = face_geometry(mesh, f);
      if (std::abs(g.normal.z) < 0.99 || g.area <= 0 || f.rings.empty()) continue;
      double zmax = -1e300;
      for (uint32_t v : f.rings[0]) zmax = std::max(zmax, mesh.vertices[v].z);
      if (zmax <= lowest + dist) out.has_ground = true;
    }
  return out;
}

std::vector<HolePlane> boundary_wall_planes(const OpenInput& open, double dist, double angle_rad,
                                            double min_length, double z_lo, double z_hi) {
  struct Group {
    Plane plane;
    BBox box;
    double length = 0;
  };
  std::vector<std::pair<double, size_t>> order;  // longest first
  for (size_t i = 0; i < open.uncovered_edges.size(); ++i) {
    const auto& [a, b] = open.uncovered_edges[i];
    order.emplace_back(-std::hypot(b.x - a.x, b.y - a.y), i);
  }
  std::stable_sort(order.begin(), order.end());
  std::vector<Group> groups;
  const double cos_a = std::cos(angle_rad);
  for (const auto& [neg_len, i] : order) {
    const auto& [a, b] = open.uncovered_edges[i];
    if (-neg_len <= dist) continue;  // (nearly) vertical edge: no vertical plane through it
    Plane pl;
    pl.n = Vec3{b.y - a.y, a.x - b.x, 0};
    pl.d = 0;
    if (!canonicalize(pl)) continue;
    pl.d = -dot(pl.n, a);
    Group* g = nullptr;
    for (auto& h : groups)
      if (std::abs(dot(h.plane.n, pl.n)) >= cos_a && std::abs(h.plane.signed_distance(a)) <= dist &&
          std::abs(h.plane.signed_distance(b)) <= dist) {
        g = &h;
        break;
      }
    if (!g) {
      groups.push_back({pl, {}, 0});
      g = &groups.back();
    }
    g->box.add(a);
    g->box.add(b);
    g->length += -neg_len;
  }
  std::vector<HolePlane> out;
  for (auto& g : groups) {
    if (g.length < min_length) continue;
    BBox b = g.box;
    b.lo = b.lo - Vec3{dist, dist, 0};
    b.hi = b.hi + Vec3{dist, dist, 0};
    b.lo.z = z_lo;
    b.hi.z = z_hi;
    out.push_back({g.plane, b, g.length * (z_hi - z_lo), {}});
  }
  return out;
}

std::vector<uint8_t> cover_triangles(const TriangleSoup& soup, const PolygonMesh& mesh) {
  std::vector<uint8_t> out(soup.triangles.size(), 0);
  for (size_t i = 0; i < soup.triangles.size(); ++i) {
    const int32_t s = i < soup.source_face.size() && soup.source_face[i] < mesh.faces.size()
                          ? mesh.faces[soup.source_face[i]].semantic
                          : -1;
    if (s >= 0 && static_cast<size_t>(s) < mesh.semantic_labels.size()) {
      const std::string& l = mesh.semantic_labels[s];
      if (l == "RoofSurface" || l == "GroundSurface") {
        out[i] = 1;
        continue;
      }
      if (l == "WallSurface" || l == "ClosureSurface" || l == "FloorSurface" || l == "CeilingSurface" ||
          l == "InteriorWallSurface")
        continue;
    }
    const auto& t = soup.triangles[i];
    const Vec3 n =
        cross(soup.vertices[t[1]] - soup.vertices[t[0]], soup.vertices[t[2]] - soup.vertices[t[0]]);
    const double l = norm(n);
    out[i] = l > 0 && std::abs(n.z) >= 0.05 * l;
  }
  return out;
}

TriangleSoup open_bottoms(const std::vector<HolePlane>& holes, const VerticalOracle& cover,
                          const VerticalOracle& surface, double dist, double angle_rad) {
  TriangleSoup out;
  const double cos_a = std::cos(angle_rad);
  for (const HolePlane& h : holes) {
    if (h.loop.size() < 3 || std::abs(h.plane.n.z) < cos_a) continue;
    std::vector<uint32_t> ring(h.loop.size());
    std::iota(ring.begin(), ring.end(), uint32_t{0});
    std::vector<std::array<uint32_t, 3>> tris;
    if (!triangulate_polygon({ring}, h.loop, tris) || tris.empty()) continue;
    // A point inside the loop: its largest triangle's centroid.
    size_t best = 0;
    double largest = -1;
    for (size_t i = 0; i < tris.size(); ++i) {
      const Vec3 &a = h.loop[tris[i][0]], &b = h.loop[tris[i][1]], &c = h.loop[tris[i][2]];
      const double area = norm(cross(b - a, c - a));
      if (area > largest) largest = area, best = i;
    }
    const Vec3 c = (h.loop[tris[best][0]] + h.loop[tris[best][1]] + h.loop[tris[best][2]]) / 3.0;
    bool below = false, above = false;
    for (double z : cover.crossings(c.x, c.y)) above |= z > c.z + dist;
    for (double z : surface.crossings(c.x, c.y)) below |= z < c.z - dist;
    if (below || !above) continue;
    const uint32_t base = static_cast<uint32_t>(out.vertices.size());
    out.vertices.insert(out.vertices.end(), h.loop.begin(), h.loop.end());
    for (const auto& t : tris) {
      out.triangles.push_back({base + t[0], base + t[1], base + t[2]});
      out.source_face.push_back(UINT32_MAX);
    }
  }
  return out;
}

double closed_volume(const TriangleSoup& soup) {
  std::unordered_map<uint64_t, int> balance;
  for (const auto& t : soup.triangles)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = t[k], b = t[(k + 1) % 3];
      if (a == b) continue;
      const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      balance[key] += a < b ? 1 : -1;
    }
  if (balance.empty()) return -1;
  for (const auto& [k, c] : balance)
    if (c != 0) return -1;
  double v = 0;
  for (const auto& t : soup.triangles)
    v += dot(soup.vertices[t[0]], cross(soup.vertices[t[1]], soup.vertices[t[2]])) / 6;
  return std::abs(v);
}

}  // namespace mc
