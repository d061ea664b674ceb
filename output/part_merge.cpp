#include "output/part_merge.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/hull.hpp"
#include "core/soup.hpp"

namespace mc::output {

int largest_neighbour(const std::vector<PolygonMesh>& meshes, size_t j) {
  if (j >= meshes.size()) return -1;
  std::vector<double> area(meshes.size(), 0);
  for (const Polygon& f : meshes[j].faces)
    if (f.neighbour >= 0 && static_cast<size_t>(f.neighbour) < meshes.size())
      area[static_cast<size_t>(f.neighbour)] += face_geometry(meshes[j], f).area;
  int best = -1;
  for (size_t k = 0; k < area.size(); ++k)
    if (area[k] > 0 && (best < 0 || area[k] > area[static_cast<size_t>(best)])) best = static_cast<int>(k);
  return best;
}

namespace {

struct PointLess {
  bool operator()(const Vec3& a, const Vec3& b) const {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  }
};

// Is q inside the face's outer ring, both projected along the normal's dominant axis?
bool inside_face(const PolygonMesh& m, const Polygon& f, const Vec3& n, const Vec3& q) {
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  auto uv = [&](const Vec3& p) {
    return ax >= ay && ax >= az ? std::pair{p.y, p.z} : ay >= az ? std::pair{p.z, p.x} : std::pair{p.x, p.y};
  };
  const auto [px, py] = uv(q);
  bool in = false;
  const auto& r = f.rings[0];
  for (size_t i = 0, j = r.size() - 1; i < r.size(); j = i++) {
    const auto [xi, yi] = uv(m.vertices[r[i]]);
    const auto [xj, yj] = uv(m.vertices[r[j]]);
    if ((yi > py) != (yj > py) && px < (xj - xi) * (py - yi) / (yj - yi) + xi) in = !in;
  }
  return in;
}

// Distance from q to the nearest edge of the face's outer ring.
double edge_distance(const PolygonMesh& m, const Polygon& f, const Vec3& q) {
  double best = INFINITY;
  const auto& r = f.rings[0];
  for (size_t i = 0; i < r.size(); ++i) {
    const Vec3 &a = m.vertices[r[i]], &b = m.vertices[r[(i + 1) % r.size()]];
    const Vec3 ab = b - a;
    const double l2 = dot(ab, ab);
    const double t = l2 > 0 ? std::clamp(dot(q - a, ab) / l2, 0.0, 1.0) : 0.0;
    best = std::min(best, norm(q - (a + ab * t)));
  }
  return best;
}

}  // namespace

size_t separate_near_touches(std::vector<PolygonMesh>& meshes, double step) {
  if (!(step > 0)) return 0;
  const double gap = 2 * step;
  std::map<Vec3, Vec3, PointLess> moves;  // old position -> new position
  for (const PolygonMesh& m : meshes)
    for (const Polygon& f : m.faces) {
      if (f.rings.empty() || f.rings[0].size() < 3) continue;
      const FaceGeometry g = face_geometry(m, f);
      if (!(g.area > 0)) continue;
      const Vec3& o = m.vertices[f.rings[0][0]];
      BBox box;
      for (uint32_t v : f.rings[0]) box.add(m.vertices[v]);
      std::vector<uint8_t> on(m.vertices.size(), 0);
      for (const auto& ring : f.rings)
        for (uint32_t v : ring) on[v] = 1;
      for (uint32_t v = 0; v < m.vertices.size(); ++v) {
        const Vec3& p = m.vertices[v];
        BBox at;
        at.add(p);
        if (on[v] || !box.contains(at, gap) || moves.count(p)) continue;
        const double s = dot(p - o, g.normal);
        if (std::abs(s) >= gap) continue;
        if (!inside_face(m, f, g.normal, p) && edge_distance(m, f, p) >= gap) continue;
        // Away from the face, on the side the vertex is on (inside the part when it is on it).
        const double side = s > 0 ? 1.0 : -1.0;
        moves[p] = p + g.normal * (side * gap - s);
      }
    }
  for (PolygonMesh& m : meshes)
    for (Vec3& p : m.vertices)
      if (auto it = moves.find(p); it != moves.end()) p = it->second;
  return moves.size();
}

std::vector<PartResult> merge_parts(const std::vector<PartResult>& parts, size_t j, size_t k,
                                    const Preprocessed& pre) {
  std::vector<PartResult> out = parts;
  PartResult& into = out[k];
  const PartResult& from = parts[j];
  into.cells.insert(into.cells.end(), from.cells.begin(), from.cells.end());
  std::sort(into.cells.begin(), into.cells.end());
  into.volume += from.volume;
  into.neighbours.insert(into.neighbours.end(), from.neighbours.begin(), from.neighbours.end());
  const PolygonMesh m = part_mesh(pre, into);
  into.hull_volume = convex_hull(m.vertices).volume;
  into.convexity = into.hull_volume > 0 ? std::min(1.0, into.volume / into.hull_volume) : 0.0;
  out.erase(out.begin() + static_cast<std::ptrdiff_t>(j));
  // Neighbour indices: j is now k (itself dropped), the indices above j shift down.
  const size_t kk = k > j ? k - 1 : k;
  for (size_t i = 0; i < out.size(); ++i) {
    std::vector<uint32_t> nb;
    for (uint32_t n : out[i].neighbours) {
      size_t m2 = n == j ? kk : (n > j ? n - 1 : n);
      if (m2 != i) nb.push_back(static_cast<uint32_t>(m2));
    }
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
    out[i].neighbours = std::move(nb);
  }
  return out;
}

}  // namespace mc::output
