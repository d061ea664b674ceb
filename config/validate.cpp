#include "config/validate.hpp"

#include <cmath>
#include <cstdio>
#include <regex>
#include <string>

#include "config/config_error.hpp"

namespace mc {
namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void finite(const char* key, double v) {
  if (!std::isfinite(v)) throw ConfigError(key, "must be a finite number");
}
// lo < v < hi (open interval).
void open_range(const char* key, double v, double lo, double hi) {
  finite(key, v);
  if (!(v > lo && v < hi))
    throw ConfigError(key, "must be in (" + fmt(lo) + ", " + fmt(hi) + "), got " + fmt(v));
}
void at_least(const char* key, double v, double lo, const char* why = "") {
  finite(key, v);
  if (!(v >= lo)) throw ConfigError(key, "must be >= " + fmt(lo) + why + ", got " + fmt(v));
}
void one_of(const char* key, const std::string& v, std::initializer_list<const char*> allowed) {
  std::string list;
  for (const char* a : allowed) {
    if (v == a) return;
    list += list.empty() ? "" : ", ";
    list += a;
  }
  throw ConfigError(key, "must be one of " + list + ", got '" + v + "'");
}

void validate_pre(const PreprocessParams& p) {
  // Resolution fields: <= 0 means automatic (see core/params.hpp), so only finiteness matters.
  finite("preprocess.cell_size", p.cell_size);
  finite("preprocess.dist_thresh", p.dist_thresh);
  finite("preprocess.max_distance", p.max_distance);
  finite("preprocess.f_d", p.f_d);
  if (!(p.f_d > 0 && p.f_d <= 1)) throw ConfigError("preprocess.f_d", "must be in (0, 1]");
  open_range("preprocess.max_angle_deg", p.max_angle_deg, 0, 90);
  at_least("preprocess.min_region", p.min_region, 1);
  open_range("preprocess.angle_thresh_deg", p.angle_thresh_deg, 0, 90);
  at_least("preprocess.min_points", p.min_points, 1);
  if (p.max_points < p.min_points)
    throw ConfigError("preprocess.max_points", "must be >= preprocess.min_points (" +
                                                   std::to_string(p.min_points) + ")");
  open_range("preprocess.inside_vote", p.inside_vote, 0, 1);
  at_least("preprocess.inconsistency", p.inconsistency, 0);
  at_least("preprocess.oracle_rays", p.oracle_rays, 1);
  at_least("preprocess.vote_batch", p.vote_batch, 0);
  finite("preprocess.min_gap", p.min_gap);
  if (!(p.min_gap >= 0)) throw ConfigError("preprocess.min_gap", "must be >= 0");
  one_of("preprocess.up_axis", p.up_axis, {"z", "y", "auto"});
  one_of("preprocess.oracle", p.oracle, {"auto", "parity", "vertical"});
  finite("preprocess.volume_check", p.volume_check);
  if (!(p.volume_check >= 0)) throw ConfigError("preprocess.volume_check", "must be >= 0 (0 = off)");
  finite("preprocess.min_component_fraction", p.min_component_fraction);
  if (!(p.min_component_fraction >= 0 && p.min_component_fraction < 1))
    throw ConfigError("preprocess.min_component_fraction", "must be in [0, 1)");
  open_range("preprocess.hausdorff_error", p.hausdorff_error, 0, 1);
}

void validate_dec(const DecomposeParams& d) {
  if (d.levels.empty()) throw ConfigError("decompose.levels", "must not be empty");
  for (std::size_t i = 0; i < d.levels.size(); ++i) {
    const std::string key = "decompose.levels[" + std::to_string(i) + "]";
    const double l = d.levels[i];
    if (!std::isfinite(l) || !(l > 0 && l <= 1)) throw ConfigError(key, "must be in (0, 1]");
    // Strictly decreasing: each level refines the previous one's parts (docs/algorithm.md §13).
    if (i > 0 && !(l < d.levels[i - 1]))
      throw ConfigError("decompose.levels", "must be strictly decreasing");
  }
  at_least("decompose.sigma", d.sigma, 0);
  at_least("decompose.k", d.k, 1);
  finite("decompose.concave_thresh", d.concave_thresh);
  // Units of π: reflex edges are > π, and nothing exceeds 2π.
  if (!(d.concave_thresh >= 1 && d.concave_thresh < 2))
    throw ConfigError("decompose.concave_thresh", "must be in [1, 2) (units of pi)");
  one_of("decompose.cut_mode", d.cut_mode, {"A", "H", "V", "HV", "HI", "VI"});
  finite("decompose.cvx_thresh", d.cvx_thresh);
  if (!(d.cvx_thresh > 0 && d.cvx_thresh <= 1)) throw ConfigError("decompose.cvx_thresh", "must be in (0, 1]");
  finite("decompose.uncut_convexity", d.uncut_convexity);
  if (!(d.uncut_convexity > 0 && d.uncut_convexity <= 1)) throw ConfigError("decompose.uncut_convexity", "must be in (0, 1]");
  if (d.max_children == 0 || d.max_children < -1)
    throw ConfigError("decompose.max_children", "must be -1 (keep all) or >= 1");
  at_least("decompose.max_candidates", d.max_candidates, 0, " (0 = all)");
  at_least("decompose.first_level_candidates", d.first_level_candidates, -1, " (-1 = max_candidates, 0 = all)");
  at_least("decompose.revisit_candidates", d.revisit_candidates, 0, " (0 = all)");
  at_least("decompose.node_budget", static_cast<double>(d.node_budget), 1);
}

void validate_massing(const MassingParams& m) {
  if (!std::isfinite(m.level) || !(m.level > 0 && m.level <= 1)) throw ConfigError("massing.level", "must be in (0, 1]");
  at_least("massing.ground_tolerance", m.ground_tolerance, 0);
  open_range("massing.stacked_angle_deg", m.stacked_angle_deg, 0, 90);
  open_range("massing.side_angle_deg", m.side_angle_deg, 0, 90);
  if (m.stacked_angle_deg + m.side_angle_deg > 90)
    throw ConfigError("massing.side_angle_deg", "must leave stacked_angle_deg + side_angle_deg <= 90");
  at_least("massing.wing_min_share", m.wing_min_share, 0);
  at_least("massing.rooftop_max_share", m.rooftop_max_share, 0);
  if (!std::isfinite(m.roof_max_fill) || !(m.roof_max_fill >= 0 && m.roof_max_fill <= 1))
    throw ConfigError("massing.roof_max_fill", "must be in [0, 1]");
  at_least("massing.podium_max_roof_share", m.podium_max_roof_share, 0);
  at_least("massing.tower_min_slenderness", m.tower_min_slenderness, 0);
  at_least("massing.tower_min_height_ratio", m.tower_min_height_ratio, 0);
  at_least("massing.courtyard_min_area", m.courtyard_min_area, 0);
}

}  // namespace

void validate(const Params& params, const RunConfig& run) {
  validate_pre(params.pre);
  validate_dec(params.dec);
  validate_massing(params.massing);
  at_least("timeout_s", params.timeout_s, 0, " (0 disables the deadline)");
  at_least("max_faces", static_cast<double>(params.max_faces), 0, " (0 = no limit)");
  at_least("threads", params.threads, 0, " (0 = all cores)");
  at_least("in_flight", run.in_flight, 0, " (0 = automatic)");

  static const std::regex lod_re("^[0-3](\\.[0-9])?$");
  if (run.lod != "highest" && !std::regex_match(run.lod, lod_re))
    throw ConfigError("lod", "must be 'highest' or a CityJSON LoD such as 2.2, got '" + run.lod +
                                 "'");
  for (std::size_t i = 0; i < run.output_levels.size(); ++i) {
    if (run.output_levels[i] >= params.dec.levels.size())
      throw ConfigError("output_levels", "level index " + std::to_string(run.output_levels[i]) +
                                             " is not in decompose.levels");
    if (i > 0 && run.output_levels[i] <= run.output_levels[i - 1])
      throw ConfigError("output_levels", "must be ascending without duplicates");
  }
  one_of("log_level", run.log_level, {"trace", "debug", "info", "warn", "error", "critical", "off"});
}

}  // namespace mc
