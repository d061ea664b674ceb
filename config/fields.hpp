// The table of configuration keys: the Params keys expanded from core/params.def (their one
// declaration), the run keys of config/run_config.hpp and the sections. The loader, the range
// checks, the JSON echo, --print-config (config/lod.yaml) and docs/config.md's key tables
// (config/reference.cpp) all walk this table.
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
  const char* note = "";             // appended to the rule, e.g. " (0 = all)"; Any: the whole rule
  std::vector<const char*> choices;  // OneOf
  // "in (0, 90)", ">= 1 (0 = all)", "one of z, y, auto"; Any: its note (a rule between keys)
  std::string text() const;
};
inline Range any() { return {}; }
// A rule checked with the relations between keys (config/config_check.cpp), shown as `text`.
inline Range rule(const char* text) { return {Range::Any, -1e308, 1e308, false, false, text, {}}; }
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

// One key of core/params.def: where it lives, what it accepts and what it means.
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

// The fields of `p`, in the order of core/params.def (lod.yaml's and the JSON echo's).
std::vector<Field> fields_of(Params& p);

// A top-level key of RunConfig (parsed by config/config.cpp, which knows its form), with what the
// reference says of it; its default is RunConfig's.
struct RunKey {
  const char* name;
  const char* type;   // as docs/config.md's "type" column
  const char* range;  // the values it accepts, in words
  const char* help;
  bool affects_outputs = true;  // as Field::affects_outputs
};
const std::vector<RunKey>& run_keys();

// A section of the YAML layout, with its help (a comment in lod.yaml, a heading in docs/config.md).
struct Section {
  const char* name;
  const char* help;
};
const std::vector<Section>& sections();

}  // namespace mc::config_detail
