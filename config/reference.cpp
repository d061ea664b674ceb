// The key table printed: config/lod.yaml (--print-config), docs/config.md's key tables
// (--print-config-reference) and the keys that never change an output.
#include <charconv>
#include <sstream>

#include "config/config.hpp"
#include "config/fields.hpp"

namespace mc {
namespace {

using config_detail::AutoDouble;
using config_detail::Field;
using config_detail::Range;

// Shortest text that reads back as the same double, in fixed notation unless that is long.
std::string yaml_number(double v) {
  char buf[400];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  if (r.ec != std::errc() || r.ptr - buf > 12) r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string yaml_value(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_float()) return yaml_number(v.get<double>());
  if (v.is_array()) {
    std::string out = "[";
    for (size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + yaml_value(v[i]);
    return out + "]";
  }
  return v.dump();
}

// `key: value` with its help (and the values it accepts, in brackets) as a comment from column 31.
void yaml_line(std::ostringstream& out, const std::string& indent, const std::string& key,
               const std::string& value, const std::string& help, const std::string& range = "") {
  std::string line = indent + key + ":" + (value.empty() ? "" : " " + value);
  std::string comment = help + (range.empty() ? "" : " [" + range + "]");
  if (!comment.empty())
    line += std::string(line.size() + 2 < 31 ? 31 - line.size() : 2, ' ') + "# " + comment;
  out << line << "\n";
}

bool is_auto(const Field& f) { return std::holds_alternative<AutoDouble>(f.ptr); }

// The values a key accepts, as lod.yaml's comments say it.
std::string range_yaml(const Field& f) { return is_auto(f) ? "> 0 or auto" : f.range.text(); }

// docs/config.md's "type" column.
const char* type_text(const Field& f) {
  return std::visit(
      [](auto ptr) -> const char* {
        using P = decltype(ptr);
        if constexpr (std::is_same_v<P, AutoDouble>) return "number or `auto`";
        else if constexpr (std::is_same_v<P, double*>) return "number";
        else if constexpr (std::is_same_v<P, bool*>) return "bool";
        else if constexpr (std::is_same_v<P, std::string*>) return "string";
        else if constexpr (std::is_same_v<P, std::vector<double>*>) return "list of numbers";
        else return "integer";
      },
      f.ptr);
}

// docs/config.md's "range" column: the Range in the reference's notation.
std::string range_markdown(const Field& f) {
  const Range& r = f.range;
  if (is_auto(f)) return "> 0";
  switch (r.kind) {
    case Range::Any:
      return r.note;
    case Range::Finite:
      return "finite";
    case Range::OneOf: {
      std::string list;
      for (const char* c : r.choices) list += (list.empty() ? "`" : ", `") + std::string(c) + "`";
      return list;
    }
    case Range::Interval: {
      std::string t = r.text();
      if (t.rfind("in ", 0) == 0) return t.substr(3);
      if (t.rfind(">= ", 0) == 0) return "≥ " + t.substr(3);
      return t;
    }
  }
  return "";
}

// A default as the reference shows it: words in code spans, numbers and lists as YAML writes them.
std::string default_markdown(const nlohmann::json& v) {
  return v.is_string() ? "`" + v.get<std::string>() + "`" : yaml_value(v);
}

void table_head(std::ostringstream& out) {
  out << "| key | type | default | range | meaning |\n|---|---|---|---|---|\n";
}
void table_row(std::ostringstream& out, const std::string& key, const std::string& type,
               const std::string& def, const std::string& range, const std::string& help) {
  out << "| `" << key << "` | " << type << " | " << def << " | " << range << " | " << help << " |\n";
}

}  // namespace

std::string config_yaml(const Params& params, const RunConfig& run) {
  const nlohmann::json j = effective_config_json(params, run);
  Params copy = params;  // fields_of needs a mutable object; nothing is written through it
  const auto fields = config_detail::fields_of(copy);
  std::ostringstream out;
  out << "# morphcut-city configuration: every key with its default. Copy it and change what you need;\n"
         "# keys you leave out keep these defaults, unknown keys are rejected. Units: model units (metres\n"
         "# for 3D BAG), degrees for angles; § = docs/algorithm.md. Reference: docs/config.md. Printed by\n"
         "# `morphcut-city --print-config` from the key table (core/params.def).\n";
  for (const auto& section : config_detail::sections()) {
    out << "\n";
    yaml_line(out, "", section.name, "", section.help);
    for (const auto& f : fields)
      if (f.section == std::string(section.name))
        yaml_line(out, "  ", f.name, yaml_value(j[f.section][f.name]), f.help, range_yaml(f));
  }
  out << "\n";
  for (const auto& f : fields)
    if (!*f.section) yaml_line(out, "", f.name, yaml_value(j[f.name]), f.help, range_yaml(f));
  for (const auto& k : config_detail::run_keys())
    yaml_line(out, "", k.name, yaml_value(j[k.name]), k.help, k.range);
  return out.str();
}

std::string config_reference_markdown() {
  const nlohmann::json j = effective_config_json(Params{}, RunConfig{});
  Params p;
  const auto fields = config_detail::fields_of(p);
  std::ostringstream out;
  for (const auto& section : config_detail::sections()) {
    out << "## `" << section.name << ":` (" << section.help << ")\n\n";
    table_head(out);
    for (const auto& f : fields)
      if (f.section == std::string(section.name))
        table_row(out, f.name, type_text(f), default_markdown(j[f.section][f.name]), range_markdown(f),
                  f.help);
    out << "\n";
  }
  out << "## Top level (the run)\n\n";
  table_head(out);
  for (const auto& f : fields)
    if (!*f.section)
      table_row(out, f.name, type_text(f), default_markdown(j[f.name]), range_markdown(f), f.help);
  for (const auto& k : config_detail::run_keys())
    table_row(out, k.name, k.type, default_markdown(j[k.name]), k.range, k.help);
  return out.str();
}

std::vector<std::string> keys_not_affecting_outputs() {
  std::vector<std::string> keys;
  Params p;
  for (const Field& f : config_detail::fields_of(p))
    if (!f.affects_outputs) keys.push_back(f.path());
  for (const auto& k : config_detail::run_keys())
    if (!k.affects_outputs) keys.push_back(k.name);
  return keys;
}

}  // namespace mc
