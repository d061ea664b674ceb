#include "config/fields.hpp"

#include <cstdio>

namespace mc::config_detail {

namespace {
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}
}  // namespace

std::string Range::text() const {
  switch (kind) {
    case Any:
      return "";
    case Finite:
      return "a finite number";
    case OneOf: {
      std::string list;
      for (const char* c : choices) list += (list.empty() ? "" : ", ") + std::string(c);
      return "one of " + list;
    }
    case Interval:
      if (hi >= 1e308) return std::string(lo_open ? "> " : ">= ") + number(lo) + note;
      return "in " + std::string(lo_open ? "(" : "[") + number(lo) + ", " + number(hi) +
             (hi_open ? ")" : "]") + note;
  }
  return "";
}

std::vector<Field> fields_of(Params& p) {
  PreprocessParams& a = p.pre;
  DecomposeParams& d = p.dec;
  return {
      {"preprocess", "cell_size", AutoDouble{&a.cell_size}, finite(),
       "sampling interval i; auto = f_d x bounding-box diagonal"},
      {"preprocess", "dist_thresh", AutoDouble{&a.dist_thresh}, finite(),
       "plane distance tolerance; auto = cell_size / 4"},
      {"preprocess", "f_d", &a.f_d, in(0, 1, true, false), "automatic resolution factor, in (0, 1]"},
      {"preprocess", "max_distance", AutoDouble{&a.max_distance}, finite(),
       "region growing: max vertex-to-plane distance; auto = dist_thresh"},
      {"preprocess", "max_angle_deg", &a.max_angle_deg, in(0, 90, true, true),
       "region growing: max normal deviation, in (0, 90)"},
      {"preprocess", "min_region", &a.min_region, at_least(1), "region growing: min faces per region"},
      {"preprocess", "angle_thresh_deg", &a.angle_thresh_deg, in(0, 90, true, true),
       "plane merge / snapping / vertical-horizontal classes, in (0, 90)"},
      {"preprocess", "min_points", &a.min_points, at_least(1), "carving: min sample points per cell"},
      {"preprocess", "max_points", &a.max_points, any(),
       "carving: max sample points per cell (>= min_points)"},
      {"preprocess", "inside_vote", &a.inside_vote, in(0, 1, true, true),
       "a cell is inside if its inside-point ratio exceeds this, in (0, 1)"},
      {"preprocess", "inconsistency", &a.inconsistency, at_least(0),
       "carving re-queue threshold, relative to the c^3 volume unit"},
      {"preprocess", "vote_batch", &a.vote_batch, at_least(0),
       "carving: points voting on a cell the input surface does not touch (0 = full vote)"},
      {"preprocess", "min_gap", &a.min_gap, at_least(0),
       "carving: a plane a hair (< δ/10) from a cell vertex may still cut a badly mislabelled cell if it "
       "keeps this distance from it (model units; 0 = never)"},
      {"preprocess", "snap_corners", &a.snap_corners, any(),
       "fitted planes sharing an input corner (4+ planes, e.g. a roof valley's eave) are made to meet there "
       "exactly, and a missing face's plane passing a hair from the line of two fitted planes goes through "
       "it"},
      {"preprocess", "oracle_rays", &a.oracle_rays, at_least(1),
       "rays per point in the inside/outside majority vote"},
      {"preprocess", "fast_path", &a.fast_path, any(),
       "an input that is a valid solid is labelled by one clean ray per point (two beside thin wedges) "
       "instead "
       "of the vote"},
      {"preprocess", "fill_enclosed", &a.fill_enclosed, any(),
       "a point no ray escapes from (horizon to zenith) is inside, whatever the parity (interior floor "
       "sheets)"},
      {"preprocess", "oracle", &a.oracle, one_of({"auto", "parity", "vertical"}),
       "inside/outside oracle: auto (parity for closed inputs, the vertical roof-over-ground vote for open "
       "ones), parity or vertical"},
      {"preprocess", "volume_check", &a.volume_check, at_least(0, " (0 = off)"),
       "cell vs independent volume estimate: beyond this relative difference a second labelling runs, and a "
       "remaining one is reported (morphcut_volume_check); 0 = off"},
      {"preprocess", "seed", &a.seed, any(), "every random choice derives from it (determinism)"},
      {"preprocess", "up_axis", &a.up_axis, one_of({"z", "y", "auto"}),
       "vertical input axis: z, y or auto (NYC crops are y-up)"},
      {"preprocess", "min_component_fraction", &a.min_component_fraction, in(0, 1, false, true),
       "drop interior components below this volume fraction; 0 keeps all"},
      {"preprocess", "hausdorff_error", &a.hausdorff_error, in(0, 1, true, true),
       "relative error bound of the Hausdorff distance (of the diagonal)"},
      {"preprocess", "compute_hausdorff", &a.compute_hausdorff, any(),
       "report the Hausdorff distance of each level's parts to the input"},
      {"decompose", "levels", &d.levels, any(), "LoD thresholds, strictly decreasing, each in (0, 1]"},
      {"decompose", "sigma", &d.sigma, at_least(0),
       "cost = g + sigma*h; 1 = optimal search, 2 = fast (paper)"},
      {"decompose", "k", &d.k, at_least(1), "concave edges per attached part in the heuristic h"},
      {"decompose", "concave_thresh", &d.concave_thresh, in(1, 2, false, true, " (units of pi)"),
       "keep concave edges with angle >= concave_thresh*pi, in [1, 2)"},
      {"decompose", "cvx_thresh", &d.cvx_thresh, in(0, 1, true, false),
       "parts with volume/hull volume >= this count as convex (not cut; may merge), in (0, 1]"},
      {"decompose", "with_bisector", &d.with_bisector, any(),
       "vertical-vertical concave lines also propose their bisector"},
      {"decompose", "cut_mode", &d.cut_mode, one_of({"A", "H", "V", "HV", "HI", "VI"}),
       "candidate plane orientations: A, H, V, HV, HI or VI"},
      {"decompose", "max_children", &d.max_children, any(),
       "best children kept per expansion; -1 keeps all (paper)"},
      {"decompose", "max_candidates", &d.max_candidates, at_least(0, " (0 = all)"),
       "top candidate planes per part by weight; 0 = all"},
      {"decompose", "first_level_candidates", &d.first_level_candidates,
       at_least(-1, " (-1 = max_candidates, 0 = all)"),
       "the same cap for the first level's whole-building searches; -1 = max_candidates, 0 = all"},
      {"decompose", "node_budget", &d.node_budget, at_least(1), "expanded search nodes per part search"},
      {"decompose", "significance_max", &d.significance_max, any(),
       "edge significance = max over samples (paper) rather than mean"},
      {"decompose", "split_chains", &d.split_chains, any(),
       "split a plane pair's concave edges into connected lines (false: one line per pair, as the research "
       "code)"},
      {"decompose", "merge_tiny_parts", &d.merge_tiny_parts, any(),
       "merge parts below 0.1 x level x volume after each level"},
      {"decompose", "revisit_boundaries", &d.revisit_boundaries, any(),
       "after each level, re-search the pieces along previous-level boundaries (fewer parts, +10-40% time)"},
      {"decompose", "revisit_candidates", &d.revisit_candidates, at_least(0, " (0 = all)"),
       "candidate planes per such search (top by weight)"},
      {"decompose", "merge_convex_parts", &d.merge_convex_parts, any(),
       "then merge neighbouring parts while the level's cost drops (union not cuttable at the level)"},
      {"decompose", "uncut_convexity", &d.uncut_convexity, in(0, 1, true, false),
       "undo a level's cuts that raise its whole-building cost if the part put back is this convex (and the "
       "building cvx_thresh); 1 = never, in (0, 1]"},
      {"massing", "level", &p.massing.level, in(0, 1, true, false),
       "the LoD level whose parts give the building features (nearest written level)"},
      {"massing", "ground_tolerance", &p.massing.ground_tolerance, at_least(0),
       "grounded: z_min within this of the building's lowest point"},
      {"massing", "stacked_angle_deg", &p.massing.stacked_angle_deg, in(0, 90, true, true),
       "shared face within this of horizontal: stacked contact, in (0, 90)"},
      {"massing", "side_angle_deg", &p.massing.side_angle_deg, in(0, 90, true, true),
       "shared face within this of vertical: side contact (else inclined), in (0, 90)"},
      {"massing", "wing_min_share", &p.massing.wing_min_share, at_least(0),
       "grounded mass with >= this x the main mass's volume: wing, else annex"},
      {"massing", "rooftop_max_share", &p.massing.rooftop_max_share, at_least(0),
       "raised mass with <= this x its support's volume: rooftop, else setback"},
      {"massing", "roof_max_fill", &p.massing.roof_max_fill, in(0, 1, false, false),
       "a raised piece with few walls filling <= this of footprint x height (a wedge ~0.5), resting on a "
       "part: "
       "roof, in [0, 1]"},
      {"massing", "podium_max_roof_share", &p.massing.podium_max_roof_share, at_least(0),
       "a tower's contact covers at most this share of its podium's footprint"},
      {"massing", "tower_min_slenderness", &p.massing.tower_min_slenderness, at_least(0),
       "a tower is at least this x as tall as its footprint is long"},
      {"massing", "tower_min_height_ratio", &p.massing.tower_min_height_ratio, at_least(0),
       "a tower is at least this x as tall as its podium"},
      {"massing", "courtyard_min_area", &p.massing.courtyard_min_area, at_least(0),
       "holes of the footprint union at least this large are courtyards (model units^2)"},
      {"massing", "thin_width", &p.massing.thin_width, at_least(0),
       "a part narrower than this in plan is a layer (wall skin, facade layer) of its neighbour's mass"},
      {"massing", "mass_height_tolerance", &p.massing.mass_height_tolerance, at_least(0),
       "pieces of one mass have their tops and bottoms within this"},
      {"massing", "mass_height_share", &p.massing.mass_height_share, in(0, 1, false, false),
       "or their tops within this x the shorter one's height (a small step on a tall block), in [0, 1]"},
      {"massing", "mass_convexity", &p.massing.mass_convexity, in(0, 1, false, false),
       "pieces of one mass are together at least this convex (volume / hull volume), in [0, 1]"},
      {"massing", "mass_shared_fraction", &p.massing.mass_shared_fraction, at_least(0),
       "pieces of one mass share a vertical face >= this x the smaller height x the smaller width"},
      {"massing", "roof_min_cover", &p.massing.roof_min_cover, in(0, 1, false, false),
       "or a wedge covering at least this share of the footprint of the part it rests on (a lean-to), in [0, "
       "1]"},
      {"massing", "roof_max_wall_share", &p.massing.roof_max_wall_share, in(0, 1, false, false),
       "a raised piece with less than this share of its own faces' area in walls, resting on a part, is "
       "roof, "
       "in [0, 1]"},
      {"massing", "storey_min_cover", &p.massing.storey_min_cover, in(0, 1, false, false),
       "a mass whose top is covered at least this much by one mass standing on it is that mass's lower "
       "storey, in [0, 1]"},
      {"", "timeout_s", &p.timeout_s, at_least(0, " (0 disables the deadline)"),
       "per-building deadline in seconds (best result so far); 0 = none"},
      {"", "max_faces", &p.max_faces, at_least(0, " (0 = no limit)"),
       "buildings with more input faces are skipped as too large; 0 = no limit"},
      {"", "threads", &p.threads, at_least(0, " (0 = all cores)"), "worker threads; 0 = all cores", false},
  };
}

}  // namespace mc::config_detail
