#include "config/config.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <system_error>

#include "config/fields.hpp"

namespace mc {
namespace {

using config_detail::AutoDouble;
using config_detail::Field;

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string unknown_key_reason(const std::string& name, const std::vector<std::string>& known) {
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const auto& k : known) {
    const std::size_t d = edit_distance(name, k);
    if (d < best_d) best_d = d, best = k;
  }
  if (best_d <= std::max<std::size_t>(2, name.size() / 3))
    return "unknown key (did you mean '" + best + "'?)";
  return "unknown key";
}

bool is_section(const std::string& name) {
  for (const auto& s : config_detail::sections())
    if (name == s.name) return true;
  return false;
}

const char* kind_name(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a mapping";
    case YAML::NodeType::Null:
      return "nothing";
    default:
      return "a scalar";
  }
}

class Loader {
 public:
  explicit Loader(std::string source) : source_(std::move(source)) {}

  LoadedConfig load(const YAML::Node& root) {
    LoadedConfig out;
    auto fields = config_detail::fields_of(out.params);
    if (!root.IsNull()) {
      if (!root.IsMap())
        fail("(root)", "expected a mapping of keys, got " + std::string(kind_name(root)), root);
      walk_top(root, fields, out);
    }
    if (output_levels_) out.run.output_levels = map_output_levels(*output_levels_, out.params);
    try {
      check_config(out.params, out.run);
    } catch (const ConfigError& e) {
      // Add the line of the offending key when the YAML set it.
      std::string base = e.key().substr(0, e.key().find('['));
      auto it = lines_.find(e.key());
      if (it == lines_.end()) it = lines_.find(base);
      if (it == lines_.end()) throw;
      throw ConfigError(e.key(), e.reason(), source_ + ":" + std::to_string(it->second));
    }
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& reason, const YAML::Node& n) const {
    const int line = n.Mark().line;
    throw ConfigError(key, reason, line >= 0 ? source_ + ":" + std::to_string(line + 1) : source_);
  }

  void note(const std::string& key, const YAML::Node& n) { lines_[key] = n.Mark().line + 1; }

  // Iterates a mapping, rejecting non-scalar and duplicate keys.
  template <class F>
  void each_key(const YAML::Node& map, const std::string& prefix, F&& f) {
    std::set<std::string> seen;
    for (const auto& kv : map) {
      if (!kv.first.IsScalar())
        fail(prefix.empty() ? "(root)" : prefix, "keys must be plain names", kv.first);
      const std::string name = kv.first.Scalar();
      const std::string path = prefix.empty() ? name : prefix + "." + name;
      if (!seen.insert(name).second) fail(path, "duplicate key", kv.first);
      note(path, kv.first);
      f(name, path, kv.first, kv.second);
    }
  }

  void walk_top(const YAML::Node& root, std::vector<Field>& fields, LoadedConfig& out) {
    std::vector<std::string> known;
    for (const auto& s : config_detail::sections()) known.push_back(s.name);
    for (const auto& f : fields)
      if (!*f.section) known.push_back(f.name);
    for (const auto& k : config_detail::run_keys()) known.push_back(k.name);

    each_key(root, "",
             [&](const std::string& name, const std::string& path, const YAML::Node& key,
                 const YAML::Node& value) {
               if (is_section(name)) {
                 walk_section(name, value, fields);
               } else if (Field* f = find(fields, "", name)) {
                 set_field(*f, value);
               } else if (name == "lod") {
                 out.run.lod = scalar_text(path, value);
               } else if (name == "log_level") {
                 out.run.log_level = scalar_text(path, value);
               } else if (name == "in_flight") {
                 if (value.IsScalar() && value.Scalar() == "auto") {
                   out.run.in_flight = 0;
                 } else {
                   out.run.in_flight = parse_int<int>(path, value);
                   if (out.run.in_flight < 1) fail(path, "must be >= 1 or auto", value);
                 }
               } else if (name == "output_levels") {
                 output_levels_ = value;
               } else {
                 fail(path, unknown_key_reason(name, known), key);
               }
             });
  }

  void walk_section(const std::string& section, const YAML::Node& node, std::vector<Field>& fields) {
    if (node.IsNull()) return;  // an empty section keeps every default
    if (!node.IsMap()) fail(section, "expected a mapping of keys, got " + std::string(kind_name(node)), node);
    std::vector<std::string> known;
    for (const auto& f : fields)
      if (section == f.section) known.push_back(f.name);
    each_key(node, section,
             [&](const std::string& name, const std::string& path, const YAML::Node& key,
                 const YAML::Node& value) {
               Field* f = find(fields, section, name);
               if (!f) fail(path, unknown_key_reason(name, known), key);
               set_field(*f, value);
             });
  }

  static Field* find(std::vector<Field>& fields, const std::string& section, const std::string& name) {
    for (auto& f : fields)
      if (section == f.section && name == f.name) return &f;
    return nullptr;
  }

  std::string scalar_text(const std::string& path, const YAML::Node& n) const {
    if (!n.IsScalar()) fail(path, std::string("expected a value, got ") + kind_name(n), n);
    return n.Scalar();
  }

  double parse_double(const std::string& path, const YAML::Node& n) const {
    std::string s = scalar_text(path, n);
    const char* b = s.data();
    const char* e = b + s.size();
    if (b != e && *b == '+') ++b;
    double v = 0;
    auto [ptr, ec] = std::from_chars(b, e, v);
    if (ec != std::errc() || ptr != e || b == e) fail(path, "expected a number, got '" + s + "'", n);
    if (!std::isfinite(v)) fail(path, "must be a finite number", n);
    return v;
  }

  template <class T>
  T parse_int(const std::string& path, const YAML::Node& n) const {
    std::string s = scalar_text(path, n);
    const char* b = s.data();
    const char* e = b + s.size();
    if (b != e && *b == '+') ++b;
    T v{};
    auto [ptr, ec] = std::from_chars(b, e, v);
    if (ec == std::errc::result_out_of_range) fail(path, "integer out of range: '" + s + "'", n);
    if (ec != std::errc() || ptr != e || b == e)
      fail(path,
           std::string("expected ") + (std::is_signed_v<T> ? "an integer" : "a non-negative integer") +
               ", got '" + s + "'",
           n);
    return v;
  }

  bool parse_bool(const std::string& path, const YAML::Node& n) const {
    const std::string s = scalar_text(path, n);
    if (s == "true" || s == "True" || s == "TRUE") return true;
    if (s == "false" || s == "False" || s == "FALSE") return false;
    fail(path, "expected true or false, got '" + s + "'", n);
  }

  void set_field(Field& f, const YAML::Node& n) {
    const std::string path = f.path();
    if (n.IsNull()) fail(path, "missing value", n);
    std::visit(
        [&](auto ptr) {
          using P = decltype(ptr);
          if constexpr (std::is_same_v<P, AutoDouble>) {
            if (n.IsScalar() && n.Scalar() == "auto") {
              *ptr.v = 0;
            } else {
              const double v = parse_double(path, n);
              if (!(v > 0)) fail(path, "must be > 0 or auto", n);
              *ptr.v = v;
            }
          } else if constexpr (std::is_same_v<P, double*>) {
            *ptr = parse_double(path, n);
          } else if constexpr (std::is_same_v<P, bool*>) {
            *ptr = parse_bool(path, n);
          } else if constexpr (std::is_same_v<P, std::string*>) {
            *ptr = scalar_text(path, n);
          } else if constexpr (std::is_same_v<P, std::vector<double>*>) {
            if (!n.IsSequence())
              fail(path, std::string("expected a list of numbers, got ") + kind_name(n), n);
            ptr->clear();
            for (std::size_t i = 0; i < n.size(); ++i)
              ptr->push_back(parse_double(path + "[" + std::to_string(i) + "]", n[i]));
          } else {
            *ptr = parse_int<std::remove_pointer_t<P>>(path, n);
          }
        },
        f.ptr);
  }

  // `all`, or threshold values that must appear in decompose.levels; stored as sorted indices.
  std::vector<std::size_t> map_output_levels(const YAML::Node& n, const Params& p) const {
    if (n.IsScalar() && n.Scalar() == "all") return {};
    if (!n.IsSequence()) fail("output_levels", "expected 'all' or a list of values from decompose.levels", n);
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < n.size(); ++i) {
      const std::string path = "output_levels[" + std::to_string(i) + "]";
      const double v = parse_double(path, n[i]);
      const auto& L = p.dec.levels;
      auto it =
          std::find_if(L.begin(), L.end(), [&](double l) { return std::abs(l - v) <= 1e-9 * std::abs(l); });
      if (it == L.end()) fail(path, "value is not one of decompose.levels", n[i]);
      const std::size_t k = static_cast<std::size_t>(it - L.begin());
      if (std::find(idx.begin(), idx.end(), k) != idx.end()) fail(path, "duplicate level", n[i]);
      idx.push_back(k);
    }
    if (idx.empty()) fail("output_levels", "must not be empty (use 'all')", n);
    std::sort(idx.begin(), idx.end());
    return idx;
  }

  std::string source_;
  std::map<std::string, int> lines_;
  std::optional<YAML::Node> output_levels_;
};

}  // namespace

LoadedConfig load_config_string(const std::string& yaml, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw ConfigError("(yaml)", "invalid YAML: " + e.msg,
                      source + (e.mark.line >= 0 ? ":" + std::to_string(e.mark.line + 1) : ""));
  }
  return Loader(source).load(root);
}

LoadedConfig load_config_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, "cannot open config file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ConfigError(path, "cannot read config file");
  return load_config_string(text.str(), path);
}

nlohmann::json effective_config_json(const Params& params, const RunConfig& run) {
  Params copy = params;  // fields_of needs a mutable object; nothing is written through it
  nlohmann::json j = nlohmann::json::object();
  for (const Field& f : config_detail::fields_of(copy)) {
    nlohmann::json& slot = *f.section ? j[f.section][f.name] : j[f.name];
    std::visit(
        [&](auto ptr) {
          if constexpr (std::is_same_v<decltype(ptr), AutoDouble>) {
            slot = *ptr.v > 0 ? nlohmann::json(*ptr.v) : nlohmann::json("auto");
          } else {
            slot = *ptr;
          }
        },
        f.ptr);
  }
  j["lod"] = run.lod;
  if (run.output_levels.empty()) {
    j["output_levels"] = "all";
  } else {
    j["output_levels"] = nlohmann::json::array();
    for (std::size_t i : run.output_levels)
      j["output_levels"].push_back(i < params.dec.levels.size() ? params.dec.levels[i] : std::nan(""));
  }
  j["in_flight"] = run.in_flight > 0 ? nlohmann::json(run.in_flight) : nlohmann::json("auto");
  j["log_level"] = run.log_level;
  return j;
}

}  // namespace mc
