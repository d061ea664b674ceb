// The convex cell complex shared by carving and cutting (docs/algorithm.md §7.1).
//
// A BSP of the padded bounding box: every cell is a convex polytope; its boundary is a set of
// convex *facets*, each facet separating exactly two cells (or a cell and the outside). The
// complex is kept conforming: a vertex inserted on an edge is inserted into every facet that
// uses the edge, so there are no T-junctions and any union of cells has a closed boundary whose
// facets match edge to edge.
//
// Exactness: every vertex is the intersection of three registry planes, built once as an exact
// CGAL EPECK point (so the DAG of every point has depth one), and every side-of-plane decision
// is an exact predicate. Double coordinates are kept beside them for measurements only.
// Mutation (split) and exact queries are single-threaded per complex; the search reads only the
// double data and combinatorial structure, which is safe to share between threads.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/plane.hpp"
#include "core/vec3.hpp"

namespace mc {

class CellComplex {
 public:
  static constexpr uint32_t kNone = UINT32_MAX;

  struct Facet {
    std::vector<uint32_t> loop;  // vertex ids; right-hand normal = +normal of `plane`
    uint32_t plane = kNone;
    uint32_t front = kNone;  // cell on the positive side of the plane (or kNone = outside)
    uint32_t back = kNone;   // cell on the negative side
    bool alive = true;
  };
  struct Cell {
    std::vector<uint32_t> facets;
    bool alive = true;
    uint32_t parent = kNone;
    uint32_t split_plane = kNone;
    uint32_t child_neg = kNone, child_pos = kNone;
  };
  struct SplitResult {
    uint32_t neg, pos;
  };

  CellComplex(PlaneRegistry& planes, const BBox& box);
  ~CellComplex();
  CellComplex(const CellComplex&) = delete;
  CellComplex& operator=(const CellComplex&) = delete;

  uint32_t root_cell() const { return 0; }
  const PlaneRegistry& planes() const { return planes_; }

  // Splits a live cell by a registry plane. Returns the two children (the original cell dies),
  // or nullopt when the plane does not cross the cell's interior.
  std::optional<SplitResult> split(uint32_t cell, uint32_t plane);

  // Exact side of a live cell: +1 / -1 when entirely on one side (touching allowed), 0 when
  // the plane crosses its interior.
  int cell_side(uint32_t cell, uint32_t plane) const;
  // The same from the cell's vertices (cell_vertices), for callers testing one cell against
  // many planes.
  int vertices_side(const std::vector<uint32_t>& vertices, uint32_t plane) const;
  // Exact side of a vertex: +1, 0, -1.
  int vertex_side(uint32_t vertex, uint32_t plane) const;
  // Exact collinearity of three vertices.
  bool collinear(uint32_t a, uint32_t b, uint32_t c) const;

  const Facet& facet(uint32_t f) const { return facets_[f]; }
  const Cell& cell(uint32_t c) const { return cells_[c]; }
  size_t num_facets() const { return facets_.size(); }
  size_t num_cells() const { return cells_.size(); }
  size_t num_vertices() const { return points_.size(); }
  const Vec3& point(uint32_t v) const { return points_[v]; }

  // The cell on the other side of facet f from cell c (kNone = outside).
  uint32_t other_side(uint32_t f, uint32_t c) const {
    return facets_[f].front == c ? facets_[f].back : facets_[f].front;
  }
  // Outward unit normal of facet f seen from cell c.
  Vec3 outward_normal(uint32_t f, uint32_t c) const;
  // The facet loop oriented outward for cell c.
  std::vector<uint32_t> outward_loop(uint32_t f, uint32_t c) const;

  // Distinct vertices of a live cell (sorted ids).
  std::vector<uint32_t> cell_vertices(uint32_t c) const;
  double cell_volume(uint32_t c) const;
  Vec3 cell_centroid(uint32_t c) const;
  BBox cell_bbox(uint32_t c) const;
  double facet_area(uint32_t f) const;
  // Live leaf descendants of a (possibly split) cell, in BSP order.
  void leaves(uint32_t c, std::vector<uint32_t>& out) const;
  std::vector<uint32_t> live_cells() const;
  // Builds the exact planes of the registry's planes added since the last call (the side
  // predicates build them on first use). Until the next plane is added, vertex_side() and
  // cell_side() then only read the complex and may run on several threads at once (CGAL's lazy
  // kernel is thread-safe).
  void prepare_side_predicates() { ensure_planes(); }

 private:
  struct Exact;  // CGAL objects, hidden to keep CGAL out of most translation units
  void ensure_planes();
  uint32_t add_vertex_from_planes(uint32_t p1, uint32_t p2, uint32_t p3);
  uint32_t add_facet(Facet f);
  void kill_facet(uint32_t f);
  void split_edge(uint32_t a, uint32_t b, uint32_t w);
  // split()'s steps (`side`: each vertex of the cell against the plane, -1/0/+1; `cap_next`: the
  // section's directed edges, outward for the negative child).
  using VertexSides = std::unordered_map<uint32_t, int>;
  void cut_crossing_edges(const std::vector<uint32_t>& facets, uint32_t plane, VertexSides& side);
  void distribute_facets(uint32_t c, const std::vector<uint32_t>& facets, uint32_t cn, uint32_t cp,
                         const VertexSides& side, std::unordered_map<uint32_t, uint32_t>& cap_next);
  void add_section(uint32_t plane, uint32_t cn, uint32_t cp,
                   const std::unordered_map<uint32_t, uint32_t>& cap_next);
  void compute_cell_measures(uint32_t c) const;

  PlaneRegistry& planes_;
  std::unique_ptr<Exact> exact_;
  std::vector<Vec3> points_;
  std::vector<Facet> facets_;
  std::vector<Cell> cells_;
  mutable std::vector<double> volume_;
  mutable std::vector<Vec3> centroid_;
  mutable std::vector<uint8_t> measured_;
};

}  // namespace mc
