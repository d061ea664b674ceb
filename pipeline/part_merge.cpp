#include "pipeline/part_merge.hpp"

#include <algorithm>

#include "core/hull.hpp"
#include "core/soup.hpp"

namespace mc::pipeline {

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

}  // namespace mc::pipeline
