#include "config/fields.hpp"

#include <cstdio>
#include <type_traits>

namespace mc::config_detail {

namespace {
std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// How core/params.def marks a key (its `kind` column).
enum class Kind { value, auto_value, run_only };

// One row of the table from one line of core/params.def.
template <class T>
Field row(const char* section, const char* name, T* member, Kind kind, Range range, const char* help) {
  FieldPtr ptr = member;
  if constexpr (std::is_same_v<T, double>)
    if (kind == Kind::auto_value) ptr = AutoDouble{member};
  return {section, name, ptr, std::move(range), help, kind != Kind::run_only};
}
}  // namespace

std::string Range::text() const {
  switch (kind) {
    case Any:
      return note;
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
  std::vector<Field> f;
#define MC_PREPROCESS_KEY(type, name, def, kind, range, help) \
  f.push_back(row("preprocess", #name, &p.pre.name, Kind::kind, range, help));
#define MC_DECOMPOSE_KEY(type, name, def, kind, range, help) \
  f.push_back(row("decompose", #name, &p.dec.name, Kind::kind, range, help));
#define MC_MASSING_KEY(type, name, def, kind, range, help) \
  f.push_back(row("massing", #name, &p.massing.name, Kind::kind, range, help));
#define MC_TOP_KEY(type, name, def, kind, range, help) \
  f.push_back(row("", #name, &p.name, Kind::kind, range, help));
#include "core/params.def"
  return f;
}

const std::vector<RunKey>& run_keys() {
  static const std::vector<RunKey> keys = {
      {"in_flight", "integer or `auto`", ">= 1",
       "buildings in flight at once (bounds memory), and the window within which the largest starts first; "
       "`auto` = max(16, 8 × threads)",
       false},
      {"lod", "string", "`highest` or `0`–`3` with one decimal (`2.2`)", "input LoD to decompose"},
      {"output_levels", "`all` or list", "values of `decompose.levels`, ascending, unique",
       "levels written as BuildingParts"},
      {"log_level", "string", "one of trace, debug, info, warn, error, critical, off",
       "what `morphcut-city` prints on stderr (spdlog's level): the run summary, cache and HTML lines at "
       "`info`, input problems at `warn`, errors at `error`; `--quiet` keeps errors only",
       false},
  };
  return keys;
}

const std::vector<Section>& sections() {
  static const std::vector<Section> s = {
      {"preprocess", "the singleton cell"},
      {"decompose", "the LoD levels"},
      {"massing", "part roles and building features, docs/massing.md"},
  };
  return s;
}

}  // namespace mc::config_detail
