#include "core/hole_planes.hpp"
#include "core/geometry.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <map>

namespace mc {

namespace {

// cos 10°: a loop whose plane is this close to horizontal is a missing horizontal face.
constexpr double kHorizontalCos = 0.984807753;

struct FaceExtent {
  BBox box;
  bool horizontal_ish = false;  // not a wall: |normal.z| above sin 10°
};

double overlap_xy(const BBox& a, const BBox& b) {
  const double w = std::min(a.hi.x, b.hi.x) - std::max(a.lo.x, b.lo.x);
  const double h = std::min(a.hi.y, b.hi.y) - std::max(a.lo.y, b.lo.y);
  return w > 0 && h > 0 ? w * h : 0.0;
}

// A horizontal loop at the lower end of the faces around it, with an input face below it, is the
// top of a gap between walls and ground (walls that stop short of the ground): the missing surface
// is the vertical band down to the ground, which the open boundary's vertical planes close, not a
// horizontal face at the walls' lower edge. (A missing roof has its walls below the loop; an open
// bottom above the lowest level has nothing below it and is kept as a floor, §6.4.)
bool gap_above_ground(const std::vector<uint32_t>& loop, const std::vector<uint32_t>& loop_faces,
                      const PolygonMesh& mesh, const std::vector<FaceExtent>& faces, const BBox& loop_box,
                      double loop_z, double dist) {
  double up = 0, total = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const double len = norm(mesh.vertices[loop[(i + 1) % loop.size()]] - mesh.vertices[loop[i]]);
    total += len;
    const BBox& fb = faces[loop_faces[i]].box;
    if ((fb.lo.z + fb.hi.z) / 2 > loop_z + dist) up += len;
  }
  if (!(total > 0) || up < 0.5 * total) return false;
  const double loop_area = (loop_box.hi.x - loop_box.lo.x) * (loop_box.hi.y - loop_box.lo.y);
  for (const FaceExtent& f : faces)
    if (f.horizontal_ish && f.box.hi.z < loop_z - dist && overlap_xy(f.box, loop_box) >= 0.5 * loop_area)
      return true;
  return false;
}

}  // namespace

std::vector<HolePlane> hole_planes(const PolygonMesh& mesh, double dist, double min_area, double lowest_z) {
  std::map<std::pair<uint32_t, uint32_t>, int> uses;            // undirected edge -> number of ring uses
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> edge_face;  // undirected edge -> (last) face using it
  std::vector<FaceExtent> faces(mesh.faces.size());
  for (uint32_t fi = 0; fi < mesh.faces.size(); ++fi) {
    const Polygon& f = mesh.faces[fi];
    Vec3 newell{0, 0, 0};
    for (const auto& r : f.rings) {
      newell += ring_area_vector(mesh.vertices, r);
      for (size_t i = 0; i < r.size(); ++i) {
        const uint32_t a = r[i], b = r[(i + 1) % r.size()];
        faces[fi].box.add(mesh.vertices[a]);
        if (a != b) {
          ++uses[{std::min(a, b), std::max(a, b)}];
          edge_face[{std::min(a, b), std::max(a, b)}] = fi;
        }
      }
    }
    const double nn = norm(newell);
    faces[fi].horizontal_ish = nn > 0 && std::abs(newell.z) / nn > 0.17364817766;  // sin 10°
  }
  std::map<uint32_t, std::vector<uint32_t>> adj;  // boundary graph
  for (const auto& [e, n] : uses)
    if (n == 1) {
      adj[e.first].push_back(e.second);
      adj[e.second].push_back(e.first);
    }
  std::vector<HolePlane> out;
  std::map<uint32_t, bool> seen;
  for (const auto& [start, nb] : adj) {
    if (seen[start]) continue;
    // Walk the component; it is a loop when every vertex has exactly two boundary neighbours.
    std::vector<uint32_t> loop{start};
    seen[start] = true;
    bool simple = nb.size() == 2;
    uint32_t prev = start, cur = nb[0];
    while (cur != start) {
      const auto& n = adj[cur];
      if (n.size() != 2 || seen[cur]) {
        simple = false;
        break;
      }
      seen[cur] = true;
      loop.push_back(cur);
      const uint32_t next = n[0] == prev ? n[1] : n[0];
      prev = cur;
      cur = next;
    }
    if (!simple) {  // mark the rest of the component so it is not walked again
      std::vector<uint32_t> stack{start};
      while (!stack.empty()) {
        const uint32_t v = stack.back();
        stack.pop_back();
        for (uint32_t w : adj[v])
          if (!seen[w]) {
            seen[w] = true;
            stack.push_back(w);
          }
      }
      continue;
    }
    if (loop.size() < 3) continue;
    // Plane by PCA, area by the Newell normal of the ordered loop.
    HolePlane h;
    std::vector<Vec3> points;
    for (uint32_t v : loop) {
      points.push_back(mesh.vertices[v]);
      h.bbox.add(mesh.vertices[v]);
    }
    h.area = norm(ring_area_vector(mesh.vertices, loop)) / 2;
    if (h.area < min_area) continue;
    Vec3 c;
    const Eigen::Matrix3d cov = centred_covariance(points, c);
    h.plane.n = normalized(principal_axes(cov).normal);
    h.plane.d = -dot(h.plane.n, c);
    if (!canonicalize(h.plane)) continue;
    double worst = 0;
    for (uint32_t v : loop) worst = std::max(worst, std::abs(h.plane.signed_distance(mesh.vertices[v])));
    if (worst > dist) continue;
    if (h.bbox.hi.z - lowest_z <= dist) continue;  // the open bottom: the ground plane caps it
    if (std::abs(h.plane.n.z) >= kHorizontalCos) {
      std::vector<uint32_t> loop_faces(loop.size());
      for (size_t i = 0; i < loop.size(); ++i) {
        const uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
        loop_faces[i] = edge_face.at({std::min(a, b), std::max(a, b)});
      }
      if (gap_above_ground(loop, loop_faces, mesh, faces, h.bbox, c.z, dist)) continue;
    }
    for (uint32_t v : loop) h.loop.push_back(mesh.vertices[v]);
    out.push_back(std::move(h));
  }
  return out;
}

}  // namespace mc
