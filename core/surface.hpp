// The boundary surface of a set of cells (a singleton cell or a part): its boundary facets,
// coplanar neighbours merged into polygons with holes, collinear vertices dropped where no other
// face needs them (docs/algorithm.md §15).
#pragma once
#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "core/complex.hpp"
#include "core/key_order.hpp"
#include "core/polygon_mesh.hpp"
#include "core/union_find.hpp"

namespace mc {

struct SurfaceFace {
  std::vector<std::vector<uint32_t>> rings;  // complex vertex ids; ring 0 outer (CCW seen from outside)
  uint32_t plane = CellComplex::kNone;       // registry plane the face lies on
  bool outward_is_plus = true;               // outward normal = +plane normal?
  bool cut = false;                          // interior face: the other side is in the solid
  uint32_t neighbour = CellComplex::kNone;   // the part across a cut face (LevelSurfaceContext)
};

struct Surface {
  std::vector<SurfaceFace> faces;
  size_t boundary_edges = 0;      // edges used once (0 for a closed surface)
  size_t nonmanifold_edges = 0;   // edges used more than twice
  std::vector<uint32_t> dropped;  // vertices left out of the rings as collinear (sorted)
  bool closed() const { return boundary_edges == 0; }
};

// Boundary facets of `cells` as (facet id, cell) pairs, outward loops via cx.outward_loop.
std::vector<std::pair<uint32_t, uint32_t>> boundary_facets(const CellComplex& cx,
                                                           const std::vector<uint32_t>& cells);

// `solid` (optional, sorted): the enclosing solid's cells; faces whose other side is in it are
// cut faces (kept apart from coplanar exterior faces when merging).
// Undirected boundary edges of `cells` (key: min << 32 | max vertex id), each with the boundary
// facets (facet, cell) using it; more than two uses = a pinch edge (cells touching along it).
std::map<uint64_t, std::vector<std::pair<uint32_t, uint32_t>>> boundary_edge_uses(
    const CellComplex& cx, const std::vector<uint32_t>& cells);

// Vertices where a boundary is pinched: its faces around the vertex form more than one fan
// (joined through edges used by exactly two faces). `uses`: edge key (min << 32 | max) -> the
// faces using the edge; `face_of` maps an element of those lists to a face id. Sorted.
template <class Uses, class FaceOf>
std::vector<uint32_t> pinch_vertices(const Uses& uses, FaceOf face_of) {
  // The (vertex, face) incidences and, for each edge used by exactly two faces, the two faces it
  // joins at each of its ends, both ordered by vertex: each vertex's fans are then found among
  // its own few faces (this runs for every part the search analyses: flat arrays, no maps).
  struct Join {
    uint32_t v, f1, f2;
  };
  std::vector<uint64_t> incidences;  // vertex << 32 | face
  std::vector<Join> unordered;
  uint32_t vertex_bound = 0;
  for (const auto& [key, inc] : uses)
    for (const uint32_t v : {static_cast<uint32_t>(key >> 32), static_cast<uint32_t>(key & 0xffffffffu)}) {
      vertex_bound = std::max(vertex_bound, v + 1);
      for (const auto& x : inc) incidences.push_back((uint64_t(v) << 32) | face_of(x));
      if (inc.size() == 2) unordered.push_back({v, face_of(inc[0]), face_of(inc[1])});
    }
  // Both ordered by vertex through a table by vertex id (core/key_order.hpp): linear but for the
  // distinct vertices' sort, where sorting every incidence is not.
  std::vector<uint64_t> node;  // vertex << 32 | face, sorted, unique
  node.reserve(incidences.size());
  for (const uint32_t i : stable_key_order(
           static_cast<uint32_t>(incidences.size()), [&](uint32_t i) { return incidences[i]; }, vertex_bound))
    if (node.empty() || node.back() != incidences[i]) node.push_back(incidences[i]);
  std::vector<Join> joins;
  joins.reserve(unordered.size());
  for (const uint32_t i : stable_key_order(
           static_cast<uint32_t>(unordered.size()),
           [&](uint32_t i) { return uint64_t(unordered[i].v) << 32; }, vertex_bound))
    joins.push_back(unordered[i]);
  std::vector<uint32_t> out;
  UnionFind fans;
  size_t j = 0;
  for (size_t i = 0; i < node.size();) {
    const uint32_t v = static_cast<uint32_t>(node[i] >> 32);
    size_t e = i + 1;
    while (e < node.size() && static_cast<uint32_t>(node[e] >> 32) == v) ++e;
    while (j < joins.size() && joins[j].v < v) ++j;
    if (e - i > 1) {
      fans.reset(e - i);
      auto local = [&](uint32_t f) {
        return static_cast<uint32_t>(
            std::lower_bound(node.begin() + i, node.begin() + e, (uint64_t(v) << 32) | f) -
            (node.begin() + i));
      };
      for (; j < joins.size() && joins[j].v == v; ++j) fans.link(local(joins[j].f1), local(joins[j].f2));
      size_t roots = 0;
      for (uint32_t x = 0; x < fans.size(); ++x) roots += fans.is_root(x);
      if (roots > 1) out.push_back(v);
    }
    i = e;
  }
  return out;
}

// For the parts of one level written side by side (docs/output-format.md §Validity): a cut face
// is split by the part across it, so that two neighbours write their common face as the same
// polygon, and the vertices in `keep` (the corners of any part's faces) stay on every ring that
// passes through them, so that no part has a T-junction where its neighbour has a corner.
struct LevelSurfaceContext {
  const std::unordered_map<uint32_t, uint32_t>* part_of = nullptr;  // leaf cell -> part index
  const std::unordered_set<uint32_t>* keep = nullptr;               // vertices never dropped
};

// `neighbour` of a face (SurfaceFace::neighbour): the part across a cut face when `level` is given.
Surface extract_surface(const CellComplex& cx, const std::vector<uint32_t>& cells,
                        const std::vector<uint32_t>* solid = nullptr, const LevelSurfaceContext& level = {});

// Converts a surface to a PolygonMesh in double coordinates shifted by `offset`.
// `label_of_face(const SurfaceFace&)` gives each face its semantic label index (or -1).
template <class LabelFn>
PolygonMesh to_polygon_mesh(const CellComplex& cx, const Surface& s, const Vec3& offset,
                            LabelFn label_of_face);

// Triangles of the boundary facets (fans of convex facets), for measurements (Hausdorff, volume).
void boundary_triangles(const CellComplex& cx, const std::vector<uint32_t>& cells, const Vec3& offset,
                        std::vector<Vec3>& vertices, std::vector<std::array<uint32_t, 3>>& triangles);

double surface_volume(const CellComplex& cx, const std::vector<uint32_t>& cells);

// ---- template implementation ----
template <class LabelFn>
PolygonMesh to_polygon_mesh(const CellComplex& cx, const Surface& s, const Vec3& offset,
                            LabelFn label_of_face) {
  PolygonMesh m;
  std::vector<uint32_t> remap;
  auto index = [&](uint32_t v) {
    if (remap.size() <= v) remap.resize(v + 1, UINT32_MAX);
    if (remap[v] == UINT32_MAX) {
      remap[v] = static_cast<uint32_t>(m.vertices.size());
      m.vertices.push_back(cx.point(v) + offset);
    }
    return remap[v];
  };
  for (const SurfaceFace& f : s.faces) {
    Polygon p;
    for (const auto& ring : f.rings) {
      std::vector<uint32_t> r;
      r.reserve(ring.size());
      for (uint32_t v : ring) r.push_back(index(v));
      p.rings.push_back(std::move(r));
    }
    p.semantic = label_of_face(f);
    m.faces.push_back(std::move(p));
  }
  return m;
}

}  // namespace mc
