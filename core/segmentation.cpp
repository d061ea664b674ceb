#include "core/segmentation.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

#include "core/geometry.hpp"
#include "core/soup.hpp"

namespace mc {

SegmentationParams segmentation_params(const PreprocessParams& p) {
  if (!(p.cell_size > 0) || !(p.dist_thresh > 0))
    throw std::invalid_argument("segmentation_params: cell_size and dist_thresh must be resolved");
  SegmentationParams s;
  s.max_distance = p.max_distance > 0 ? p.max_distance : p.dist_thresh;
  s.max_angle_deg = p.max_angle_deg;
  s.angle_thresh_deg = p.angle_thresh_deg;
  s.dist_thresh = p.dist_thresh;
  s.min_area = p.cell_size * p.cell_size;
  s.min_region = p.min_region;
  return s;
}

namespace {

// Area-weighted second moments of a point set; the plane fit is their smallest principal axis.
struct Moments {
  double w = 0;
  Eigen::Vector3d s = Eigen::Vector3d::Zero();
  Eigen::Matrix3d ss = Eigen::Matrix3d::Zero();
  void add(const Vec3& p, double weight) {
    const Eigen::Vector3d e(p.x, p.y, p.z);
    w += weight;
    s += weight * e;
    ss += weight * e * e.transpose();
  }
  void add(const Moments& o) {
    w += o.w;
    s += o.s;
    ss += o.ss;
  }
  // Plane through the weighted centroid; `hint` orients it and stands in when degenerate.
  Plane fit(const Vec3& hint) const {
    const Eigen::Vector3d c = s / w;
    const Eigen::Matrix3d cov = ss / w - c * c.transpose();
    const PrincipalAxes axes = principal_axes(cov);
    Vec3 n = hint;
    if (axes.eigenvalues(1) > 1e-12 * std::max(1.0, axes.eigenvalues(2))) n = normalized(axes.normal);
    if (dot(n, hint) < 0) n = -n;
    const Vec3 cv{c(0), c(1), c(2)};
    return Plane{n, -dot(n, cv)};
  }
};

struct Face {
  std::vector<uint32_t> verts;  // distinct position ids
  Vec3 normal;                  // unit, zero when degenerate
  double area = 0;
  Moments moments;
};

struct Workspace {
  std::vector<Vec3> pos;  // distinct positions, centred on the bounding box
  std::vector<Face> faces;
  std::vector<std::vector<uint32_t>> adj;
};

struct BitsHash {
  size_t operator()(const Vec3& p) const {
    uint64_t h = 1469598103934665603ull;
    for (double c : {p.x, p.y, p.z}) {
      uint64_t b;
      std::memcpy(&b, &c, 8);
      h = (h ^ b) * 1099511628211ull;
      h ^= h >> 29;
    }
    return static_cast<size_t>(h);
  }
};

Workspace build_workspace(const PolygonMesh& mesh, Vec3* centre) {
  Workspace ws;
  *centre = bbox_center(mesh);
  std::unordered_map<Vec3, uint32_t, BitsHash> id_of;
  std::vector<uint32_t> pos_id(mesh.vertices.size());
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    auto [it, fresh] = id_of.emplace(mesh.vertices[i], static_cast<uint32_t>(ws.pos.size()));
    if (fresh) ws.pos.push_back(mesh.vertices[i] - *centre);
    pos_id[i] = it->second;
  }
  BBox box;
  for (const Vec3& p : ws.pos) box.add(p);
  const double tiny_area = 1e-12 * box.diagonal() * box.diagonal();

  std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> edges;
  ws.faces.resize(mesh.faces.size());
  for (uint32_t fi = 0; fi < mesh.faces.size(); ++fi) {
    const Polygon& poly = mesh.faces[fi];
    Face& f = ws.faces[fi];
    const FaceGeometry g = face_geometry(mesh, poly);
    f.normal = g.normal;
    f.area = g.area;
    for (const auto& ring : poly.rings)
      for (size_t k = 0; k < ring.size(); ++k) {
        const uint32_t a = pos_id[ring[k]], b = pos_id[ring[(k + 1) % ring.size()]];
        f.verts.push_back(a);
        if (a != b) edges[{std::min(a, b), std::max(a, b)}].push_back(fi);
      }
    std::sort(f.verts.begin(), f.verts.end());
    f.verts.erase(std::unique(f.verts.begin(), f.verts.end()), f.verts.end());
    // Vertex weights: the face's area shared by its vertices (a floor keeps slivers fittable).
    const double w = (f.area + tiny_area) / static_cast<double>(std::max<size_t>(1, f.verts.size()));
    for (uint32_t v : f.verts) f.moments.add(ws.pos[v], w);
  }
  ws.adj.resize(mesh.faces.size());
  for (const auto& [e, fs] : edges)
    for (uint32_t a : fs)
      for (uint32_t b : fs)
        if (a != b) ws.adj[a].push_back(b);
  for (auto& a : ws.adj) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  return ws;
}

double max_distance(const Workspace& ws, const std::vector<uint32_t>& verts, const Plane& pl,
                    double stop_above) {
  double m = 0;
  for (uint32_t v : verts) {
    m = std::max(m, std::abs(pl.signed_distance(ws.pos[v])));
    if (m > stop_above) break;
  }
  return m;
}

// Seeds: faces whose one-ring is best fitted by a plane come first. The RMS residual is bucketed
// (1% of max_distance) so float noise does not override the deterministic tie-breaks: larger
// area first, then smaller index.
std::vector<uint32_t> seed_order(const Workspace& ws, double max_dist) {
  const size_t n = ws.faces.size();
  std::vector<double> bucket(n, 0);
  for (size_t f = 0; f < n; ++f) {
    Moments m = ws.faces[f].moments;
    for (uint32_t g : ws.adj[f]) m.add(ws.faces[g].moments);
    const Plane pl = m.fit(ws.faces[f].normal);
    const Eigen::Vector3d nn(pl.n.x, pl.n.y, pl.n.z);
    // Weighted mean squared distance = n^T (ss/w) n + 2d n·(s/w) + d^2.
    const double msd = nn.dot(m.ss * nn) / m.w + 2 * pl.d * nn.dot(m.s) / m.w + pl.d * pl.d;
    const double rms = std::sqrt(std::max(0.0, msd));
    bucket[f] = max_dist > 0 ? std::floor(rms / (0.01 * max_dist)) : rms;
  }
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    if (bucket[a] != bucket[b]) return bucket[a] < bucket[b];
    if (ws.faces[a].area != ws.faces[b].area) return ws.faces[a].area > ws.faces[b].area;
    return a < b;
  });
  return order;
}

struct Region {
  std::vector<uint32_t> faces;
  std::vector<uint32_t> verts;  // distinct position ids, sorted
  Moments moments;
  Plane plane;
  double area = 0;
  Vec3 normal_sum;  // area-weighted face normals, flipped onto the plane: majority orientation
};

void finish_region(const Workspace& ws, Region& r) {
  r.verts.clear();
  r.area = 0;
  Vec3 hint = ws.faces[r.faces[0]].normal;
  for (uint32_t f : r.faces) {
    r.verts.insert(r.verts.end(), ws.faces[f].verts.begin(), ws.faces[f].verts.end());
    r.area += ws.faces[f].area;
  }
  std::sort(r.verts.begin(), r.verts.end());
  r.verts.erase(std::unique(r.verts.begin(), r.verts.end()), r.verts.end());
  r.plane = r.moments.fit(hint);
  // Majority vote of face orientations (by area) decides the normal's sign.
  double vote = 0;
  for (uint32_t f : r.faces) vote += ws.faces[f].area * (dot(ws.faces[f].normal, r.plane.n) >= 0 ? 1 : -1);
  if (vote < 0) r.plane = Plane{-r.plane.n, -r.plane.d};
}

std::vector<Region> grow_regions(const Workspace& ws, const SegmentationParams& p) {
  const double cos_max = std::cos(p.max_angle_deg * M_PI / 180.0);
  const size_t n = ws.faces.size();
  std::vector<int32_t> owner(n, -1);
  std::vector<Region> regions;
  std::vector<uint32_t> level, next;
  for (uint32_t seed : seed_order(ws, p.max_distance)) {
    if (owner[seed] != -1 || !(norm(ws.faces[seed].normal) > 0.5)) continue;
    const int32_t id = static_cast<int32_t>(regions.size());
    Region r;
    r.faces = {seed};
    r.moments = ws.faces[seed].moments;
    owner[seed] = id;
    Plane pl = r.moments.fit(ws.faces[seed].normal);
    level = {seed};
    // Breadth-first, refitting after each complete ring (like CGAL's Region_growing).
    while (!level.empty()) {
      next.clear();
      for (uint32_t f : level)
        for (uint32_t g : ws.adj[f]) {
          if (owner[g] != -1) continue;
          const Face& fg = ws.faces[g];
          if (std::abs(dot(fg.normal, pl.n)) < cos_max) continue;
          if (max_distance(ws, fg.verts, pl, p.max_distance) > p.max_distance) continue;
          owner[g] = id;
          r.faces.push_back(g);
          r.moments.add(fg.moments);
          next.push_back(g);
        }
      if (!next.empty()) pl = r.moments.fit(pl.n);
      std::swap(level, next);
    }
    if (static_cast<int>(r.faces.size()) < p.min_region) {
      for (uint32_t f : r.faces) owner[f] = -1;  // released: later regions may take them
      continue;
    }
    std::sort(r.faces.begin(), r.faces.end());
    finish_region(ws, r);
    regions.push_back(std::move(r));
  }
  return regions;
}

// Near-duplicate merge (docs/algorithm.md §3.2, mesh variant of the same-plane test), largest regions first;
// each region joins the best matching group (smallest max distance), which is then refit.
std::vector<Region> merge_regions(const Workspace& ws, std::vector<Region> regions,
                                  const SegmentationParams& p) {
  std::sort(regions.begin(), regions.end(), [](const Region& a, const Region& b) {
    if (a.area != b.area) return a.area > b.area;
    return a.faces[0] < b.faces[0];
  });
  const double cos_t = std::cos(p.angle_thresh_deg * M_PI / 180.0);
  std::vector<Region> groups;
  for (Region& r : regions) {
    int best = -1;
    double best_d = 0;
    for (size_t gi = 0; gi < groups.size(); ++gi) {
      const Region& g = groups[gi];
      if (std::abs(dot(g.plane.n, r.plane.n)) < cos_t) continue;
      const double d1 = max_distance(ws, r.verts, g.plane, p.dist_thresh);
      if (d1 > p.dist_thresh) continue;
      const double d2 = max_distance(ws, g.verts, r.plane, p.dist_thresh);
      if (d2 > p.dist_thresh) continue;
      const double d = std::max(d1, d2);
      if (best < 0 || d < best_d) {
        best = static_cast<int>(gi);
        best_d = d;
      }
    }
    if (best < 0) {
      groups.push_back(std::move(r));
      continue;
    }
    Region& g = groups[best];
    g.faces.insert(g.faces.end(), r.faces.begin(), r.faces.end());
    std::sort(g.faces.begin(), g.faces.end());
    g.moments.add(r.moments);
    finish_region(ws, g);
  }
  return groups;
}

}  // namespace

std::vector<PlaneRegion> segment_planes(const PolygonMesh& mesh, const SegmentationParams& p) {
  Vec3 centre;
  const Workspace ws = build_workspace(mesh, &centre);
  std::vector<Region> groups = merge_regions(ws, grow_regions(ws, p), p);

  std::vector<PlaneRegion> out;
  for (Region& g : groups) {
    if (g.area < p.min_area) continue;
    PlaneRegion pr;
    pr.plane = Plane{g.plane.n, g.plane.d - dot(g.plane.n, centre)};  // back to input coordinates
    pr.faces = std::move(g.faces);
    pr.area = g.area;
    for (uint32_t v : g.verts) pr.bbox.add(ws.pos[v] + centre);
    std::map<int32_t, double> label_area;
    for (uint32_t f : pr.faces)
      if (mesh.faces[f].semantic >= 0) label_area[mesh.faces[f].semantic] += ws.faces[f].area;
    double best = -1;
    for (const auto& [label, a] : label_area)
      if (a > best) {
        best = a;
        pr.semantic = label;
      }
    out.push_back(std::move(pr));
  }
  std::sort(out.begin(), out.end(), [](const PlaneRegion& a, const PlaneRegion& b) {
    if (a.area != b.area) return a.area > b.area;
    return a.faces[0] < b.faces[0];
  });
  return out;
}

}  // namespace mc
