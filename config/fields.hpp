// The table of YAML keys that map one-to-one onto Params fields, with the values each accepts and
// its help. Loader, validation, JSON echo, --print-config and config/lod.yaml (printed from it)
// all walk this one table, so a new Params field needs one entry here.
#pragma once
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "core/params.hpp"

namespace mc::config_detail {

// A double whose value <= 0 means "auto" in Params; YAML spells it `auto`.
struct AutoDouble {
  double* v;
};

using FieldPtr =
    std::variant<double*, AutoDouble, int*, int64_t*, uint64_t*, bool*, std::string*, std::vector<double>*>;

// The values a key accepts beyond its type (checked by check_config(); shown by --print-config).
struct Range {
  enum Kind { Any, Finite, Interval, OneOf } kind = Any;
  double lo = -1e308, hi = 1e308;  // Interval: bounds (an infinite bound is not shown)
  bool lo_open = false, hi_open = false;
  const char* note = "";             // appended to the rule, e.g. " (0 = all)"
  std::vector<const char*> choices;  // OneOf
  std::string text() const;          // "(0, 90)", ">= 1 (0 = all)", "one of z, y, auto"; "" for Any
};
inline Range any() { return {}; }
inline Range finite() {
  Range r;
  r.kind = Range::Finite;
  return r;
}
inline Range in(double lo, double hi, bool lo_open, bool hi_open, const char* note = "") {
  return {Range::Interval, lo, hi, lo_open, hi_open, note, {}};
}
inline Range at_least(double lo, const char* note = "") {
  return {Range::Interval, lo, 1e308, false, false, note, {}};
}
inline Range one_of(std::vector<const char*> choices) {
  return {Range::OneOf, -1e308, 1e308, false, false, "", std::move(choices)};
}

// One key: where it lives, what it accepts and what it means. Its default is the Params member's
// initialiser (core/params.hpp); config/lod.yaml is this table printed (a test compares them).
struct Field {
  const char* section;  // "preprocess", "decompose", "massing" or "" for top level
  const char* name;
  FieldPtr ptr;
  Range range;
  const char* help;
  // False for settings that never change an output (the outputs are byte-identical for any value):
  // the cache key, merge-reports' config hash and the HTML page's config leave them out.
  bool affects_outputs = true;
  std::string path() const { return *section ? std::string(section) + "." + name : name; }
};

// The fields of `p`, in the order lod.yaml and the JSON echo list them.
std::vector<Field> fields_of(Params& p);

}  // namespace mc::config_detail
