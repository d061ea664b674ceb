// What each output file holds of one building (docs/output-format.md). The job builds one
// feature with every level's parts; the writer derives from it:
//   - the annotated input: every object and geometry of the input as it was, plus the Building's
//     morphcut_* attributes, no parts;
//   - one view per written level: that level's parts are the Building's BuildingParts at the
//     source LoD, and the input geometry at that LoD is taken out of the way (its objects,
//     attributes and other LoDs stay), so no two objects of a Building overlap at one LoD.
// A building without parts at a level (failed, skipped) is the input in every view.
#pragma once
#include <string>

#include "io/cityjson_types.hpp"

namespace mc::output {

// OUT.city.json -> OUT.level-<t>.city.json (also .city.jsonl, .json, .jsonl); t printed with %g.
std::string level_output_path(const std::string& output, double threshold);

// The feature without morphcut parts (vertices no object uses any more dropped).
mc::io::Feature annotated_view(const mc::io::Feature& f);

// The feature as level `threshold` shows it; `lod` is the input LoD the parts replace
// (BuildingOutcome::lod). The Building gets `morphcut_level` = threshold when it has parts there.
mc::io::Feature level_view(const mc::io::Feature& f, const mc::io::Header& h, double threshold,
                           const std::string& lod);

// True for a BuildingPart a morphcut run added (it carries `morphcut_level`).
bool is_morphcut_part(const nlohmann::json& object);

// Removes BuildingParts and attributes a previous morphcut run added, so that running on an
// output is the same as running on its input (parts are recognised by `morphcut_level`).
// Returns the number of objects removed.
size_t strip_previous_parts(mc::io::Feature& f);

// Drops vertices no object refers to, keeping the order of the others.
void compact_vertices(mc::io::Feature& f);

}  // namespace mc::output
