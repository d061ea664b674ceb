#include "config/fields.hpp"

namespace mc::config_detail {

std::vector<Field> fields_of(Params& p) {
  PreprocessParams& a = p.pre;
  DecomposeParams& d = p.dec;
  return {
      {"preprocess", "cell_size", AutoDouble{&a.cell_size}},
      {"preprocess", "dist_thresh", AutoDouble{&a.dist_thresh}},
      {"preprocess", "f_d", &a.f_d},
      {"preprocess", "max_distance", AutoDouble{&a.max_distance}},
      {"preprocess", "max_angle_deg", &a.max_angle_deg},
      {"preprocess", "min_region", &a.min_region},
      {"preprocess", "angle_thresh_deg", &a.angle_thresh_deg},
      {"preprocess", "min_points", &a.min_points},
      {"preprocess", "max_points", &a.max_points},
      {"preprocess", "inside_vote", &a.inside_vote},
      {"preprocess", "inconsistency", &a.inconsistency},
      {"preprocess", "vote_batch", &a.vote_batch},
      {"preprocess", "min_gap", &a.min_gap},
      {"preprocess", "snap_corners", &a.snap_corners},
      {"preprocess", "oracle_rays", &a.oracle_rays},
      {"preprocess", "fill_enclosed", &a.fill_enclosed},
      {"preprocess", "oracle", &a.oracle},
      {"preprocess", "volume_check", &a.volume_check},
      {"preprocess", "seed", &a.seed},
      {"preprocess", "up_axis", &a.up_axis},
      {"preprocess", "min_component_fraction", &a.min_component_fraction},
      {"preprocess", "hausdorff_error", &a.hausdorff_error},
      {"preprocess", "compute_hausdorff", &a.compute_hausdorff},
      {"decompose", "levels", &d.levels},
      {"decompose", "sigma", &d.sigma},
      {"decompose", "k", &d.k},
      {"decompose", "concave_thresh", &d.concave_thresh},
      {"decompose", "cvx_thresh", &d.cvx_thresh},
      {"decompose", "with_bisector", &d.with_bisector},
      {"decompose", "cut_mode", &d.cut_mode},
      {"decompose", "same_vol_factor", &d.same_vol_factor},
      {"decompose", "max_children", &d.max_children},
      {"decompose", "max_candidates", &d.max_candidates},
      {"decompose", "first_level_candidates", &d.first_level_candidates},
      {"decompose", "node_budget", &d.node_budget},
      {"decompose", "significance_max", &d.significance_max},
      {"decompose", "split_chains", &d.split_chains},
      {"decompose", "merge_tiny_parts", &d.merge_tiny_parts},
      {"decompose", "revisit_boundaries", &d.revisit_boundaries},
      {"decompose", "revisit_candidates", &d.revisit_candidates},
      {"decompose", "merge_convex_parts", &d.merge_convex_parts},
      {"decompose", "uncut_convexity", &d.uncut_convexity},
      {"", "timeout_s", &p.timeout_s},
      {"", "max_faces", &p.max_faces},
      {"", "threads", &p.threads},
  };
}

}  // namespace mc::config_detail
