// Every algorithm parameter with its default. config/ fills this from YAML (or from the paper's
// per-sample `NAME.off_config.json`); core/ only reads it. Reference: docs/config.md.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace mc {

struct PreprocessParams {
  // Resolution. When cell_size <= 0 it is derived from the bounding-box diagonal:
  // cell_size = f_d * diagonal, dist_thresh = cell_size / 4 (paper §4 "automatic resolution").
  double cell_size = 0;    // sampling interval i (model units); <= 0 means automatic
  double dist_thresh = 0;  // δ (model units); <= 0 means cell_size / 4
  double f_d = 0.01;       // automatic resolution factor
  // Region growing (plane segmentation). <= 0 distances mean "= dist_thresh".
  double max_distance = 0;
  double max_angle_deg = 10;
  int min_region = 1;
  double angle_thresh_deg = 10;  // θa: plane merge, candidate snapping, plane classes
  // Carving.
  int min_points = 50;
  int max_points = 2000;
  double inside_vote = 0.5;     // a cell is inside if its inside-point ratio exceeds this
  double inconsistency = 1e-3;  // re-queue threshold, relative to the cell volume c^3 unit
  int vote_batch = 9;           // points voting on a cell the input surface does not touch (0 = full vote)
  // A cell left with only hair-blocked planes (a vertex within δ/10) is still cut by one whose
  // hair-close vertices all keep at least this distance (model units: 2 x a 1 mm output grid),
  // when at least 20% of the cell is mislabelled. 0 = never.
  double min_gap = 0.002;
  // The output grid's step near the building (model units), set per file by the pipeline from the
  // output's transform (not a configuration key; 0 = none). No plane may pass closer than one step
  // to a vertex without going through it, nor a hair-blocked plane cut closer than two steps: such
  // vertices would collapse on the grid (docs/algorithm.md §7.4).
  double output_grid = 0;
  // Fitted planes sharing an input corner (4+ planes) are made to meet there exactly, and a missing
  // face's plane passing a hair from the line of two fitted planes goes through that line
  // (core/corner_snap.hpp). false = the paper's behaviour (planes as fitted).
  bool snap_corners = true;
  int oracle_rays = 5;  // rays per point for the inside/outside majority vote
  // An input that is a valid solid (closed, 2-manifold, outward, not self-intersecting; exact
  // predicates) is labelled by one clean ray per point (two that agree beside a thin wedge), the
  // vote only where a ray is not clean (docs/algorithm.md §6.6).
  bool fast_path = true;
  // With the fast path, a cell the surface only grazes is voted in a band along its facets
  // (docs/algorithm.md §7.3). Not a configuration key: tests compare with the full vote.
  bool grazed_cells = true;
  // The parity vote labels the points of a cell the surface touches by regions: boxes of them
  // that no triangle touches are decided by a few points each (docs/design.md "Regions, not
  // points"). Not a configuration key: tests and benchmarks compare with the point-by-point vote.
  bool region_votes = true;
  // With the fast path, a cell the surface touches is labelled by its exact inside volume (the
  // surface's columns over it, core/column_volume.hpp) instead of sample points (docs/design.md
  // "Inside volume by columns"). Not a configuration key: tests compare with the votes.
  bool column_volumes = true;
  // Points the parity vote calls outside but that no ray (horizon to zenith) escapes from are
  // inside: storeys whose floors are modelled as sheets inside the solid (core/oracle.hpp).
  bool fill_enclosed = true;
  // Which inside/outside oracle labels the carving (docs/algorithm.md §6.4): "auto" = the parity
  // vote (§6.1–§6.3) for closed and nearly closed inputs, the vertical roof-over-ground vote for
  // open ones; "parity" or "vertical" force one.
  std::string oracle = "auto";
  // Volume check (§6.5): when the cell's volume and an independent estimate of the volume the
  // input encloses differ by more than this fraction, the other oracle labels the carving a second
  // time and the closer result is kept; a difference that remains is reported. 0 = no check.
  double volume_check = 0.05;
  uint64_t seed = 1;  // every random choice derives from it (determinism)
  // "z", "y" or "auto": which input axis is vertical (NYC crops are y-up).
  std::string up_axis = "auto";
  // Disjoint interior components smaller than this fraction of the total volume are dropped
  // (and reported); 0 keeps every component.
  double min_component_fraction = 0.0;
  // Hausdorff fidelity: relative error bound of the bounded-error computation (of the diagonal).
  double hausdorff_error = 0.001;
  bool compute_hausdorff = true;
};

struct DecomposeParams {
  std::vector<double> levels{0.1, 0.01, 0.001, 0.0001};  // LoD thresholds, strictly decreasing
  double sigma = 2.0;                                    // ε of cost = g + ε·h; 1 = optimal search
  int k = 4;                                             // concave edges per attached part in h
  double concave_thresh = 1.0;  // in units of π: keep lines with angle >= concave_thresh·π
  // Parts with V/V_CH >= cvx_thresh count as convex: no concave lines, Δ = 0 in the objective,
  // never cut, and neighbours whose union is that convex may merge. The research code reads
  // this key but never uses it (docs/algorithm.md §9.6); 1 = only exactly convex parts.
  double cvx_thresh = 0.995;
  bool with_bisector = true;
  std::string cut_mode = "A";  // A, H, V, HV, HI, VI
  int max_children = 64;       // best children kept per expansion (-1 = all, as RC)
  int max_candidates = 12;     // top-K candidate planes per part by weight (0 = all)
  // The same cap for the first level's searches (whole components; -1 = max_candidates, 0 = all).
  // There is one such search per component and every later level only refines inside its parts,
  // so a wider choice there can pay; measured mixed (docs/design.md), hence opt-in.
  int first_level_candidates = -1;
  int64_t node_budget = 20000;   // expanded nodes per search
  bool significance_max = true;  // D(e) = max over samples (paper) instead of mean (RC)
  bool merge_tiny_parts = true;
  // After each level but the first, re-search the pieces along the boundary of two neighbouring
  // previous parts as one part (a coarse level's boundary can force extra pieces at a finer one),
  // with this many candidate planes (top by weight). Better parts for more time (decompose.cpp).
  bool revisit_boundaries = false;
  int revisit_candidates = 4;
  bool merge_convex_parts = true;  // after each level, merge neighbours while the level's cost drops
  // After each level, undo cuts that raise the level's whole-building cost (the searches use
  // per-part normalisers, docs/algorithm.md §11.2) when every part put back is at least this convex and
  // the building stays at least cvx_thresh convex (decompose.cpp, refuse_costly_cuts); 1 = never.
  double uncut_convexity = 0.95;
  // Concave-line grouping: true splits a plane pair's edges into connected chains (docs/algorithm.md
  // §9.3); false groups every edge of a plane pair into one line, as the research code does.
  bool split_chains = true;
};

// Massing analytics of the written parts (massing/massing.hpp, docs/massing.md): contact
// kinds, part roles and building features. Lengths in model units, angles in degrees.
struct MassingParams {
  double level = 0.01;            // the LoD level whose parts give the building features
  double ground_tolerance = 0.5;  // a part is grounded if its z_min is within this of the building's lowest z
  double stacked_angle_deg = 10;  // a shared face within this of horizontal: stacked contact
  double side_angle_deg = 10;     // a shared face within this of vertical: side contact (else inclined)
  double wing_min_share = 0.2;    // grounded part >= this x the main part's volume: wing (else annex)
  double rooftop_max_share = 0.1;  // raised part <= this x its support's volume: rooftop (else setback)
  double roof_max_fill = 0.6;      // raised piece filling <= this of its footprint x height (a wedge): roof
  double podium_max_roof_share =
      0.5;  // a tower's contact covers at most this share of the podium's footprint
  double tower_min_slenderness =
      1.0;  // a tower's height >= this x its footprint's length (its longer plan side)
  double tower_min_height_ratio = 1.0;  // a tower's height >= this x the podium's height
  double courtyard_min_area = 10;       // footprint holes at least this large (model units^2) are courtyards
  // Masses (docs/massing.md, "Masses").
  double thin_width = 1.0;             // a part narrower than this in plan is a layer of its neighbour's mass
  double mass_height_tolerance = 0.5;  // pieces of one mass have their tops and bottoms within this
  double mass_height_share = 0.05;     // or their tops within this x the shorter one's height
  double mass_convexity = 0.95;        // and together are about as convex as one part (V / V_hull)
  double mass_shared_fraction = 0.5;   // and share a vertical face >= this x min height x min width
  double roof_max_wall_share =
      0.35;                       // a raised piece with fewer own walls than this, resting on a part, is roof
  double roof_min_cover = 0.25;   // or covering this share of the footprint of the part it rests on
  double storey_min_cover = 0.9;  // a mass covered this much by one mass on it is that mass's storey
};

struct Params {
  PreprocessParams pre;
  DecomposeParams dec;
  MassingParams massing;
  double timeout_s = 60;  // per-building deadline; <= 0 disables
  // Buildings with more input faces are skipped ("too large"): a mesh error or a whole terrain
  // filed as one Building would otherwise hold a worker for its whole deadline. 0 = no limit.
  int64_t max_faces = 50000;
  int threads = 0;  // 0 = all cores
};

}  // namespace mc
