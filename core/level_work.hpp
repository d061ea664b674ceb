// The parts of one LoD level while the driver and the level passes work on them
// (docs/algorithm.md §13–§14): a part as its live cells (`LevelPart`), a part prepared for its
// search (`PreparedPart`: refined cells, candidate sides, analysed root), and all parts of a level
// as one cell space (`LevelSpace`) for analysing parts and unions of parts. Internal to core/.
#pragma once
#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include "core/complex.hpp"
#include "core/part.hpp"
#include "core/preprocess.hpp"
#include "core/search.hpp"

namespace mc {

// The analyses of a level's whole parts, shared by the level passes that follow the searches
// (the convex merge, the undo of costly cuts and the level's statistics each analyse every
// part; most parts are the same from one pass to the next). An analysis depends only on the
// part's cells, the space (`cells`: its cells in local order, which fixes the bits), the level's
// context and the complex, which these passes do not change (docs/algorithm.md §14).
struct LevelAnalyses {
  std::vector<uint32_t> cells;                                  // the space's cells
  std::map<std::vector<uint32_t>, PartAnalysis> by_part_cells;  // sorted cells of a part -> analysis
};

}  // namespace mc

namespace mc::level {

// One part of a level being worked on.
struct LevelPart {
  std::vector<uint32_t> cells;  // live cells
  int component = 0;
};

// A part searched at this level: its refined space and search inputs.
struct PreparedPart {
  CellSpace space;
  SearchInput input;
  PartAnalysis root;
  bool search = false;
};

// The live leaves of `cells` (split since they were recorded), ascending.
std::vector<uint32_t> current_leaves(const CellComplex& cx, const std::vector<uint32_t>& cells);

// The owners other than `self` of the cells across the facets of `cells`, ascending; `owner_of`
// maps a cell to its owner, or to CellComplex::kNone for a cell outside every part.
template <class OwnerOf>
std::vector<uint32_t> neighbour_owners(const CellComplex& cx, const std::vector<uint32_t>& cells,
                                       uint32_t self, const OwnerOf& owner_of) {
  std::vector<uint32_t> nb;
  for (uint32_t c : cells)
    for (uint32_t f : cx.cell(c).facets) {
      const uint32_t o = cx.other_side(f, c);
      const uint32_t w = o == CellComplex::kNone ? CellComplex::kNone : owner_of(o);
      if (w != CellComplex::kNone && w != self) nb.push_back(w);
    }
  std::sort(nb.begin(), nb.end());
  nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  return nb;
}

// Owner lookup in a cell -> owner map.
inline auto lookup_in(const std::unordered_map<uint32_t, uint32_t>& m) {
  return [&m](uint32_t c) {
    auto it = m.find(c);
    return it == m.end() ? CellComplex::kNone : it->second;
  };
}

AnalysisContext make_context(const Preprocessed& pre, const DecomposeParams& p, double level);

// Refines a part's cells by its candidate planes (the only step of a part's preparation that
// changes the complex; sequential). `finish` builds the part's space and root analysis
// afterwards: refining a neighbouring part splits the facets the two share, so a space built
// before that would keep dead facets (stale loops: boundary edges used once, false pinched
// vertices that refuse every cut). Hence all parts of a level are refined first, then all spaces
// are built.
PreparedPart refine(Preprocessed& pre, const LevelPart& w, const AnalysisContext& ctx);
// The refined space and the cells on each candidate's positive side (exact predicates: one
// thread per complex).
void finish_space(const Preprocessed& pre, PreparedPart& pr, const AnalysisContext& ctx);
// The search's root: the refined space analysed (reads only; several at once are fine).
void finish_root(const Preprocessed& pre, PreparedPart& pr, const AnalysisContext& ctx);
void finish(const Preprocessed& pre, PreparedPart& pr, const AnalysisContext& ctx);
PreparedPart prepare(Preprocessed& pre, const LevelPart& w, const AnalysisContext& ctx);

// The cells of all parts of a level as one space (analysis of parts and of unions of parts).
struct LevelSpace {
  CellSpace space;
  std::unordered_map<uint32_t, uint32_t> local;  // global cell id -> index in `space`
  LevelSpace(const CellComplex& cx, const std::vector<LevelPart>& work);
  Bits bits(const LevelPart& w) const;
};

// Analysis only: generated candidate planes are not registered.
extern const PlaneResolver kNoNewPlanes;

// Every part of a level analysed, in parallel (the analysis only reads the complex); in order.
// With `ctx.parts`, a part analysed before in the same space is taken from there.
std::vector<PartAnalysis> analyze_parts(const CellSpace& space, const LevelSpace& ls,
                                        const std::vector<LevelPart>& work, const AnalysisContext& ctx);

// A part's convexity V/V_CH as reported (1 for an exactly convex part).
inline double reported_convexity(const PartAnalysis& info) {
  return info.delta == 0 && !info.nearly_convex ? 1.0 : info.convexity();
}
// A part's term V·(V/V_CH) of the level's volume-weighted convexity.
inline double weighted_convexity(const PartAnalysis& info) { return info.volume * reported_convexity(info); }

}  // namespace mc::level
