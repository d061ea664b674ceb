#include "config/config_check.hpp"

#include <cmath>
#include <cstdio>
#include <regex>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "config/config_error.hpp"
#include "config/fields.hpp"

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
void at_least(const char* key, double v, double lo, const char* why = "") {
  finite(key, v);
  if (!(v >= lo)) throw ConfigError(key, "must be >= " + fmt(lo) + why + ", got " + fmt(v));
}
void one_of(const std::string& key, const std::string& v, const std::vector<const char*>& allowed) {
  std::string list;
  for (const char* a : allowed) {
    if (v == a) return;
    list += list.empty() ? "" : ", ";
    list += a;
  }
  throw ConfigError(key, "must be one of " + list + ", got '" + v + "'");
}

// The range a key declares (core/params.def, read through config/fields.cpp).
void check_number(const std::string& key, double v, const config_detail::Range& r) {
  using config_detail::Range;
  if (r.kind == Range::Any) return;
  if (!std::isfinite(v)) throw ConfigError(key, "must be a finite number");
  if (r.kind != Range::Interval) return;
  const bool ok = (r.lo_open ? v > r.lo : v >= r.lo) && (r.hi_open ? v < r.hi : v <= r.hi);
  if (!ok) throw ConfigError(key, "must be " + r.text() + ", got " + fmt(v));
}

void check_field(const config_detail::Field& f) {
  std::visit(
      [&](auto ptr) {
        using T = decltype(ptr);
        if constexpr (std::is_same_v<T, std::string*>) {
          if (f.range.kind == config_detail::Range::OneOf) one_of(f.path(), *ptr, f.range.choices);
        } else if constexpr (std::is_same_v<T, config_detail::AutoDouble>) {
          check_number(f.path(), *ptr.v, f.range);
        } else if constexpr (std::is_same_v<T, bool*> || std::is_same_v<T, std::vector<double>*>) {
          // no range: a bool is a bool; decompose.levels has its own rule below
        } else {
          check_number(f.path(), static_cast<double>(*ptr), f.range);
        }
      },
      f.ptr);
}

// The rules that relate keys to each other or to list elements.
void validate_relations(const Params& params) {
  const PreprocessParams& p = params.pre;
  if (p.max_points < p.min_points)
    throw ConfigError("preprocess.max_points",
                      "must be >= preprocess.min_points (" + std::to_string(p.min_points) + ")");
  const DecomposeParams& d = params.dec;
  if (d.levels.empty()) throw ConfigError("decompose.levels", "must not be empty");
  for (std::size_t i = 0; i < d.levels.size(); ++i) {
    const std::string key = "decompose.levels[" + std::to_string(i) + "]";
    const double l = d.levels[i];
    if (!std::isfinite(l) || !(l > 0 && l <= 1)) throw ConfigError(key, "must be in (0, 1]");
    // Strictly decreasing: each level refines the previous one's parts (docs/algorithm.md §13).
    if (i > 0 && !(l < d.levels[i - 1])) throw ConfigError("decompose.levels", "must be strictly decreasing");
  }
  if (d.max_children == 0 || d.max_children < -1)
    throw ConfigError("decompose.max_children", "must be -1 (keep all) or >= 1");
  const MassingParams& m = params.massing;
  if (m.stacked_angle_deg + m.side_angle_deg > 90)
    throw ConfigError("massing.side_angle_deg", "must leave stacked_angle_deg + side_angle_deg <= 90");
}

}  // namespace

void check_config(const Params& params, const RunConfig& run) {
  Params copy = params;  // fields_of needs a mutable object; nothing is written through it
  for (const config_detail::Field& f : config_detail::fields_of(copy)) check_field(f);
  validate_relations(params);
  at_least("in_flight", run.in_flight, 0, " (0 = automatic)");

  static const std::regex lod_re("^[0-3](\\.[0-9])?$");
  if (run.lod != "highest" && !std::regex_match(run.lod, lod_re))
    throw ConfigError("lod", "must be 'highest' or a CityJSON LoD such as 2.2, got '" + run.lod + "'");
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
