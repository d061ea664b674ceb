// The level passes that follow each level's searches (docs/algorithm.md §14), one file each:
// revisiting previous boundaries (revisit_boundaries.cpp, opt-in), the tiny-part merge
// (merge_tiny_parts.cpp), the convex merge (merge_convex_parts.cpp) and the undo of costly cuts
// (undo_costly_cuts.cpp). The LoD driver (decompose.cpp) runs them in that order. Internal to core/.
#pragma once
#include <vector>

#include "core/decompose.hpp"
#include "core/level_work.hpp"
#include "core/objective.hpp"

namespace mc::level {

// §14.1: the pieces along the boundary of two previous parts searched again as one part.
void revisit_boundaries(Preprocessed& pre, const DecomposeParams& p, std::vector<LevelPart> prev,
                        std::vector<LevelPart>& work, const AnalysisContext& ctx, const Objective& obj,
                        Clock::time_point deadline, LevelResult& level);
// §14.2: parts smaller than v_min merged into a neighbour, smallest first.
// `hulls` (optional): the building's hull cache.
void merge_tiny_parts(const CellComplex& cx, std::vector<LevelPart>& parts, double v_min,
                      HullCache* hulls = nullptr);
// §14.3: neighbouring parts merged while that lowers the level's cost.
void merge_convex_neighbours(const Preprocessed& pre, std::vector<LevelPart>& work,
                             const AnalysisContext& ctx, const Objective& obj);
// §14.4: cuts of a level that raise its whole-building cost put back.
void refuse_costly_cuts(const Preprocessed& pre, const DecomposeParams& p, const std::vector<LevelPart>& prev,
                        std::vector<LevelPart>& work, const AnalysisContext& ctx, const Objective& obj);

}  // namespace mc::level
