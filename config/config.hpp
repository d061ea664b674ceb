// Loading the run configuration (YAML, see config/lod.yaml for every key with its default) into
// mc::Params + mc::RunConfig, and echoing the effective configuration for the run report.
//
// YAML layout: sections `preprocess:`, `decompose:` and `massing:` whose keys are the Params field
// names, plus top-level `timeout_s`, `max_faces`, `threads`, `lod`, `output_levels`, `in_flight`,
// `log_level`. Every key is declared once, in core/params.def.
// `cell_size`, `dist_thresh`, `max_distance` accept `auto`; `in_flight` accepts `auto`;
// `output_levels` is `all` or a list of values taken from `decompose.levels`. Missing keys keep
// their defaults; unknown keys, duplicate keys, wrong types and out-of-range values throw
// ConfigError whose message starts with the key path and ends with "(file:line)".
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "config/config_error.hpp"
#include "config/paper_config.hpp"
#include "config/run_config.hpp"
#include "config/config_check.hpp"
#include "core/params.hpp"

namespace mc {

struct LoadedConfig {
  Params params;
  RunConfig run;
};

// Throws ConfigError (also for an unreadable file or invalid YAML).
LoadedConfig load_config_file(const std::string& path);
// `source` names the text in error messages.
LoadedConfig load_config_string(const std::string& yaml, const std::string& source = "<config>");

// The configuration in the YAML layout (JSON is YAML, so this loads back to the same values).
nlohmann::json effective_config_json(const Params& params, const RunConfig& run);

// The keys whose value never changes an output (threads, in_flight, log_level: outputs are
// byte-identical for any thread count), from the key table; and an effective config without them,
// which is what the cache key, merge-reports and the HTML page compare.
std::vector<std::string> keys_not_affecting_outputs();
template <class Json>  // nlohmann::json or nlohmann::ordered_json, in the YAML layout
Json outputs_config_json(Json c) {
  if (!c.is_object()) return c;
  for (const std::string& key : keys_not_affecting_outputs()) {
    const auto dot = key.find('.');
    if (dot == std::string::npos) c.erase(key);
    else if (c.contains(key.substr(0, dot)) && c[key.substr(0, dot)].is_object())
      c[key.substr(0, dot)].erase(key.substr(dot + 1));
  }
  return c;
}

// The configuration as a YAML file with every key's help (config/lod.yaml is this for the defaults).
std::string config_yaml(const Params& params, const RunConfig& run);
// docs/config.md's key tables (Markdown): every key's type, default, range and meaning, per section.
std::string config_reference_markdown();

}  // namespace mc
