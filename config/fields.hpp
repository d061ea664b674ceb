// The table of YAML keys that map one-to-one onto Params fields. Loader, JSON echo and the
// lod.yaml test all walk this one table, so a new Params field needs one line here.
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

using FieldPtr = std::variant<double*, AutoDouble, int*, int64_t*, uint64_t*, bool*, std::string*,
                              std::vector<double>*>;

struct Field {
  const char* section;  // "preprocess", "decompose" or "" for top level
  const char* name;
  FieldPtr ptr;
  std::string path() const { return *section ? std::string(section) + "." + name : name; }
};

// The fields of `p`, in the order lod.yaml and the JSON echo list them.
std::vector<Field> fields_of(Params& p);

}  // namespace mc::config_detail
