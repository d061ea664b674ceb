#include "core/hole_planes.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <map>

namespace mc {

std::vector<HolePlane> hole_planes(const PolygonMesh& mesh, double dist, double min_area, double lowest_z) {
  std::map<std::pair<uint32_t, uint32_t>, int> uses;  // undirected edge -> number of ring uses
  for (const Polygon& f : mesh.faces)
    for (const auto& r : f.rings)
      for (size_t i = 0; i < r.size(); ++i) {
        const uint32_t a = r[i], b = r[(i + 1) % r.size()];
        if (a != b) ++uses[{std::min(a, b), std::max(a, b)}];
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
    Vec3 c{0, 0, 0}, newell{0, 0, 0};
    for (uint32_t v : loop) c += mesh.vertices[v];
    c = c / static_cast<double>(loop.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    HolePlane h;
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vec3 p = mesh.vertices[loop[i]] - c, q = mesh.vertices[loop[(i + 1) % loop.size()]] - c;
      const Eigen::Vector3d e(p.x, p.y, p.z);
      cov += e * e.transpose();
      newell += cross(p, q);
      h.bbox.add(mesh.vertices[loop[i]]);
    }
    h.area = norm(newell) / 2;
    if (h.area < min_area) continue;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    const Eigen::Vector3d n = es.eigenvectors().col(0);  // smallest eigenvalue
    h.plane.n = normalized(Vec3{n.x(), n.y(), n.z()});
    h.plane.d = -dot(h.plane.n, c);
    if (!canonicalize(h.plane)) continue;
    double worst = 0;
    for (uint32_t v : loop) worst = std::max(worst, std::abs(h.plane.signed_distance(mesh.vertices[v])));
    if (worst > dist) continue;
    if (h.bbox.hi.z - lowest_z <= dist) continue;  // the open bottom: the ground plane caps it
    for (uint32_t v : loop) h.loop.push_back(mesh.vertices[v]);
    out.push_back(std::move(h));
  }
  return out;
}

}  // namespace mc
