// Parts as sets of convex cells (docs/algorithm.md §9).
//
// A `CellSpace` fixes a set of live cells of the complex (a search root after its refinement by
// the root's candidate planes, or a whole singleton component) and gives them local indices; a
// part is then a bitset over those indices, so cutting, merging and comparing parts is pure
// combinatorics. Everything here reads only double coordinates and the combinatorial structure
// of the complex, so it is safe to use from several threads at once.
#pragma once
#include <bit>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/complex.hpp"
#include "core/hull_cache.hpp"
#include "core/params.hpp"

namespace mc {

using Bits = std::vector<uint64_t>;

inline bool test_bit(const Bits& b, uint32_t i) { return (b[i >> 6] >> (i & 63)) & 1u; }
inline void set_bit(Bits& b, uint32_t i) { b[i >> 6] |= uint64_t(1) << (i & 63); }
// Calls f(i) for every set bit, ascending, a word at a time (a part is often a few cells of a
// large space).
template <class F>
void for_each_bit(const Bits& b, F&& f) {
  for (size_t w = 0; w < b.size(); ++w)
    for (uint64_t word = b[w]; word != 0; word &= word - 1)
      f(static_cast<uint32_t>(w * 64 + static_cast<unsigned>(std::countr_zero(word))));
}
uint64_t hash_bits(const Bits& b);
size_t count_bits(const Bits& b);

struct CellSpace {
  static constexpr uint32_t kOut = UINT32_MAX;
  const CellComplex* cx = nullptr;
  std::vector<uint32_t> cells;  // global ids; local index = position
  struct Side {
    uint32_t facet;
    uint32_t other;  // local index of the cell across the facet, or kOut
  };
  std::vector<std::vector<Side>> sides;         // per local cell
  std::vector<double> volume;                   // per local cell
  std::vector<std::vector<uint32_t>> vertices;  // per local cell: global vertex ids
  size_t words() const { return (cells.size() + 63) / 64; }
  Bits all() const;
};

CellSpace make_space(const CellComplex& cx, const std::vector<uint32_t>& cells);

// A reflex "concave line" of a part (docs/algorithm.md §9.3) with its significance weight (§9.5).
struct ConcaveLine {
  uint32_t p1 = 0, p2 = 0;  // the two face planes
  Vec3 n1, n2;              // outward normals of the two faces
  Vec3 dir, point;          // the line
  double t0 = 0, t1 = 0;    // extent along dir from point
  double angle = 0;         // interior dihedral angle (radians, > π)
  double weight = 0;        // L · D (paper Eq. 7)
  double length() const { return t1 - t0; }
};

struct LevelAnalyses;  // core/level_work.hpp

// Settings that fix how parts are analysed at one LoD level.
struct AnalysisContext {
  const DecomposeParams* dec = nullptr;
  double dist = 0;                 // δ
  double angle_rad = 0;            // θa
  double a_diag = 1;               // area of the input box's vertical diagonal plane
  double level = 0;                // LoD threshold l (significance: weight >= l * a_diag)
  BBox box;                        // the input box (snapping)
  HullCache* hulls = nullptr;      // the building's hulls (core/hull_cache.hpp); null = computed each time
  LevelAnalyses* parts = nullptr;  // the level passes' analyses of whole parts (core/level_work.hpp)
};

// Maps a generated candidate plane (bisector, vertical or horizontal plane through a line) to a
// plane id: snapping to an existing plane, registering a new one, or rejecting it (nullopt).
using PlaneResolver =
    std::function<std::optional<uint32_t>(const Plane& generated, const std::vector<uint32_t>& pool)>;

// A part as the analysis sees it (docs/algorithm.md §9–§10): its cells in a space, volumes, hull,
// concave lines and candidate cutting planes. The other stages' part types: LevelPart and
// PreparedPart (core/level_work.hpp), PartResult (core/decompose.hpp).
struct PartAnalysis {
  Bits bits;
  uint64_t hash = 0;
  size_t cell_count = 0;
  double volume = 0;
  double hull_volume = 0;
  double delta = 0;            // Δ = V_CH − V (0 for convex parts)
  int e_all = 0;               // concave lines with non-negligible weight
  int e_sig = 0;               // lines significant at this level
  int pinch_edges = 0;         // boundary edges shared by more than two boundary faces, plus pinched vertices
  bool nearly_convex = false;  // V/V_CH >= cvx_thresh but not exactly convex: counted as convex
  std::vector<ConcaveLine> lines;    // reflex lines, by decreasing weight
  std::vector<uint32_t> candidates;  // cutting planes, by decreasing weight
  double convexity() const { return hull_volume > 0 ? volume / hull_volume : 0.0; }
};

PartAnalysis analyze_part(const CellSpace& s, Bits bits, const AnalysisContext& ctx,
                          const PlaneResolver& resolve);

// Whether the boundary of a set of cells has an edge used by more than two boundary facets, or
// a vertex where two separate fans of boundary facets meet.
bool has_pinch_edge(const CellComplex& cx, const std::vector<uint32_t>& cells);

// Connected components (through shared facets) of the cells of `bits`, ascending by first cell.
std::vector<Bits> components(const CellSpace& s, const Bits& bits);

}  // namespace mc
