#include "output/validate_report.hpp"

#include <cmath>
#include <cstdio>

namespace mc::output {

using nlohmann::json;

namespace {
// Measures in the report are rounded: the last bits of a volume are noise, the file must not be.
double rounded(double v, double step) { return std::round(v / step) * step; }
}  // namespace

json to_json(const ObjectReport& r) {
  json j = {{"id", r.id}, {"type", r.type}, {"valid", r.valid()}};
  json errors = json::array();
  for (const auto& e : r.errors)
    errors.push_back({{"code", e.code}, {"name", e.name}, {"message", e.message}});
  j["errors"] = std::move(errors);
  if (!r.note.empty()) j["note"] = r.note;
  if (r.level) j["morphcut_level"] = *r.level;
  if (r.volume) j["volume"] = rounded(*r.volume, 1e-6);
  if (r.convexity) j["convexity"] = rounded(*r.convexity, 1e-6);
  return j;
}

json to_json(const ValidationCounts& c) {
  return {{"features", c.features},
          {"objects", c.objects},
          {"buildings", c.buildings},
          {"buildings_with_parts", c.buildings_with_parts},
          {"buildings_without_parts", c.buildings_without_parts},
          {"invalid_buildings", c.invalid_buildings},
          {"parts", c.parts},
          {"valid_parts", c.valid_parts},
          {"invalid_parts", c.invalid_parts},
          {"other_invalid_objects", c.other_invalid_objects},
          {"overlap_tests", c.overlap_tests},
          {"max_volume_deviation", rounded(c.max_volume_deviation, 1e-12)}};
}

JsonValidationWriter::JsonValidationWriter(std::ostream& out, const std::string& file,
                                           const ValidateOptions& opt)
    : out_(out) {
  const json tol = {{"planarity_m", opt.planarity},
                    {"normals_deg", opt.normals_deg},
                    {"overlap_m3", opt.overlap},
                    {"snap_m", opt.snap},
                    {"volume_relative", opt.volume_rel}};
  out_ << "{\"file\":" << json(file).dump() << ",\"tolerances\":" << tol.dump() << ",\"objects\":[";
}

void JsonValidationWriter::object(const ObjectReport& r) {
  out_ << (first_ ? "\n" : ",\n") << to_json(r).dump();
  first_ = false;
}

void JsonValidationWriter::finish(const ValidationSummary& s) {
  out_ << "\n],\"counts\":" << to_json(s.counts).dump()
       << ",\"file_problems\":" << json(s.file_problems).dump()
       << ",\"valid\":" << (s.valid() ? "true" : "false") << "}\n";
}

void write_text_errors(std::ostream& out, const ObjectReport& r) {
  for (const auto& e : r.errors)
    out << r.id << " (" << r.type << "): " << e.code << " " << e.name << ": " << e.message << "\n";
}

void write_text_summary(std::ostream& out, const ValidationSummary& s) {
  const auto& c = s.counts;
  for (const auto& p : s.file_problems) out << s.file << ": file problem: " << p << "\n";
  char share[32] = "-";
  if (c.parts)
    std::snprintf(share, sizeof share, "%.2f%%",
                  100.0 * static_cast<double>(c.valid_parts) / static_cast<double>(c.parts));
  out << s.file << ": " << c.buildings << " buildings (" << c.buildings_with_parts << " with parts, "
      << c.buildings_without_parts << " without, " << c.invalid_buildings << " invalid), " << c.parts
      << " parts: " << c.valid_parts << " valid (" << share << "), " << c.invalid_parts << " invalid; "
      << c.other_invalid_objects << " other invalid objects; " << c.overlap_tests
      << " exact overlap tests; largest volume deviation " << c.max_volume_deviation << "\n"
      << (s.valid() ? "VALID" : "INVALID") << "\n";
}

}  // namespace mc::output
