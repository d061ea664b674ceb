// Reading the MorphCut paper's per-sample `NAME.off_config.json` (docs/config.md) into Params.
//
// Keys map to Params fields (min_cut_factor -> dec.levels, max_angle -> pre.max_angle_deg, ...).
// Optional keys the file omits take the research code's defaults (min_cut_factor
// [0.1, 0.01, 0.001], max_children -1, cut_mode A, with_bisector true),
// so a paper run means what it meant there; Params fields the paper has no key for keep ours.
// Unknown keys, missing required keys and unsupported objective terms (max_vol, symmetry,
// central, decentral set to true) are tolerated and reported in `warnings`: these are the
// paper's files, not ours. Wrong types and out-of-range values throw ConfigError naming the
// paper's key (e.g. "min_cut_factor: must be strictly decreasing (…_config.json)").
#pragma once
#include <string>
#include <vector>

#include "core/params.hpp"

namespace mc {

Params load_paper_config(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace mc
