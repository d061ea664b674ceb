#include "config/paper_config.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "config/run_config.hpp"
#include "config/config_check.hpp"

namespace mc {
namespace {

using nlohmann::json;

// Paper key -> our YAML key path, to rename validation errors back into the file's terms.
const std::map<std::string, std::string> kPaperToOurs = {
    {"max_distance", "preprocess.max_distance"},
    {"max_angle", "preprocess.max_angle_deg"},
    {"min_region", "preprocess.min_region"},
    {"angle_thresh", "preprocess.angle_thresh_deg"},
    {"dist_thresh", "preprocess.dist_thresh"},
    {"cell_size", "preprocess.cell_size"},
    {"concave_thresh", "decompose.concave_thresh"},
    {"cvx_thresh", "decompose.cvx_thresh"},
    {"min_points", "preprocess.min_points"},
    {"max_points", "preprocess.max_points"},
    {"sigma", "decompose.sigma"},
    {"min_cut_factor", "decompose.levels"},
    {"max_children", "decompose.max_children"},
    {"cut_mode", "decompose.cut_mode"},
    {"with_bisector", "decompose.with_bisector"},
};
// Required in the research code (it crashes without them); we warn and keep a default instead.
const char* const kRequired[] = {"max_distance", "max_angle", "min_region",     "angle_thresh",
                                 "dist_thresh",  "cell_size", "concave_thresh", "min_points",
                                 "max_points",   "sigma"};
// Read by the research code but without effect there (dead parameters, or file-name only), or
// without a counterpart here.
// (cvx_thresh is dead in the research code too, but here it does what it was meant for.)
const char* const kInert[] = {"extended_plane_ch", "fewer_comp",
                              // RC's duplicate tolerance: the search finds duplicates by exact part sets
                              "same_vol_factor"};
// Extra objective terms of the paper's Appendix D, not implemented here.
const char* const kTerms[] = {"max_vol", "symmetry", "central", "decentral"};
const char* const kTermWeights[] = {"max_vol_weight", "symmetry_weight", "central_weight",
                                    "decentral_weight"};

template <std::size_t N>
bool listed(const char* const (&list)[N], const std::string& key) {
  return std::find(std::begin(list), std::end(list), key) != std::end(list);
}

class PaperReader {
 public:
  PaperReader(const json& j, std::string file) : j_(j), file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& reason) const {
    throw ConfigError(key, reason, file_);
  }

  double number(const std::string& key) const {
    const json& v = j_.at(key);
    if (!v.is_number()) fail(key, "expected a number, got " + v.dump());
    const double d = v.get<double>();
    if (!std::isfinite(d)) fail(key, "must be a finite number");
    return d;
  }
  int integer(const std::string& key) const {
    const double d = number(key);  // 100.0 is accepted: RapidJSON configs are hand-written
    if (d != std::floor(d) || std::abs(d) > 2e9) fail(key, "expected an integer, got " + j_.at(key).dump());
    return static_cast<int>(d);
  }
  bool boolean(const std::string& key) const {
    const json& v = j_.at(key);
    if (!v.is_boolean()) fail(key, "expected true or false, got " + v.dump());
    return v.get<bool>();
  }
  std::string string(const std::string& key) const {
    const json& v = j_.at(key);
    if (!v.is_string()) fail(key, "expected a string, got " + v.dump());
    return v.get<std::string>();
  }
  std::vector<double> numbers(const std::string& key) const {
    const json& v = j_.at(key);
    if (!v.is_array()) fail(key, "expected a list of numbers, got " + v.dump());
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!v[i].is_number())
        fail(key + "[" + std::to_string(i) + "]", "expected a number, got " + v[i].dump());
      out.push_back(v[i].get<double>());
    }
    return out;
  }

 private:
  const json& j_;
  std::string file_;
};

}  // namespace

Params load_paper_config(const std::string& path, std::vector<std::string>* warnings) {
  std::vector<std::string> local;
  std::vector<std::string>& warn = warnings ? *warnings : local;
  warn.clear();

  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, "cannot open config file");
  json j;
  try {
    j = json::parse(in);
  } catch (const json::parse_error& e) { throw ConfigError(path, std::string("invalid JSON: ") + e.what()); }
  if (!j.is_object()) throw ConfigError("(root)", "expected a JSON object", path);
  PaperReader r(j, path);

  Params p;
  // The research code's defaults for its optional keys (docs/config.md).
  p.dec.levels = {0.1, 0.01, 0.001};
  p.dec.max_children = -1;
  p.dec.cut_mode = "A";
  p.dec.with_bisector = true;

  for (const char* k : kRequired)
    if (!j.contains(k)) warn.push_back(std::string("missing required key '") + k + "'; using the default");

  for (const auto& [key, value] : j.items()) {
    if (key == "max_distance") p.pre.max_distance = r.number(key);
    else if (key == "max_angle") p.pre.max_angle_deg = r.number(key);
    else if (key == "min_region") p.pre.min_region = r.integer(key);
    else if (key == "angle_thresh") p.pre.angle_thresh_deg = r.number(key);
    else if (key == "dist_thresh") p.pre.dist_thresh = r.number(key);
    else if (key == "cell_size") p.pre.cell_size = r.number(key);
    else if (key == "concave_thresh") p.dec.concave_thresh = r.number(key);
    else if (key == "cvx_thresh") p.dec.cvx_thresh = r.number(key);
    else if (key == "min_points") p.pre.min_points = r.integer(key);
    else if (key == "max_points") p.pre.max_points = r.integer(key);
    else if (key == "sigma") p.dec.sigma = r.number(key);
    else if (key == "min_cut_factor") p.dec.levels = r.numbers(key);
    else if (key == "max_children") p.dec.max_children = r.integer(key);
    else if (key == "cut_mode") p.dec.cut_mode = r.string(key);
    else if (key == "with_bisector") p.dec.with_bisector = r.boolean(key);
    else if (listed(kInert, key)) {
      if (key == "fewer_comp") (void)r.boolean(key);  // type-checked, then ignored like RC does
      else (void)r.number(key);
    } else if (listed(kTerms, key)) {
      if (r.boolean(key)) warn.push_back("'" + key + "' objective term is not supported; ignored");
    } else if (listed(kTermWeights, key)) {
      (void)r.number(key);
    } else {
      warn.push_back("unknown key '" + key + "' ignored");
    }
  }

  // Resolution distances are given explicitly in the paper's files: zero or less is a mistake,
  // not a request for automatic resolution.
  for (const char* k : {"cell_size", "dist_thresh", "max_distance"})
    if (j.contains(k) && !(r.number(k) > 0)) r.fail(k, "must be > 0");

  try {
    check_config(p, RunConfig{});
  } catch (const ConfigError& e) {
    const std::string base = e.key().substr(0, e.key().find('['));
    for (const auto& [paper, ours] : kPaperToOurs)
      if (ours == base) throw ConfigError(paper + e.key().substr(base.size()), e.reason(), path);
    throw ConfigError(e.key(), e.reason(), path);
  }
  return p;
}

}  // namespace mc
