#include "report/report.hpp"

#include <cmath>
#include <filesystem>
#include <system_error>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/errors.hpp"
#include "io/scratch_file.hpp"
#include "report/level_json.hpp"

namespace mc::report {

using namespace mc::massing;

using json = nlohmann::ordered_json;

namespace {
// JSON has no NaN: unknown numbers are null.
json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }
// Timings rounded to microseconds: more digits are noise and only bloat the report.
json secs(double v) { return std::round(v * 1e6) / 1e6; }

std::string parent_dir(const std::string& path) {
  const std::string d = std::filesystem::path(path).parent_path().string();
  return d.empty() ? "." : d;
}
}  // namespace

json building_report(const BuildingOutcome& b) {
  json j = {{"id", b.id}, {"status", b.status}};
  if (!b.reason.empty()) j["reason"] = b.reason;
  j["lod"] = b.lod;
  json levels = json::array();
  for (const auto& l : b.levels) {
    json lj = level_json(l);                 // report/level_json.hpp
    for (const auto& lm : b.massing.levels)  // part roles (massing/massing.hpp)
      if (lm.index == l.index) {
        json roles = json::object();
        for (const char* r : {"main", "wing", "annex", "podium", "tower", "setback", "rooftop"}) {
          int k = 0;
          for (const auto& mm : lm.masses) k += mm.role == r;
          if (k) roles[r] = k;
        }
        lj["roles"] = std::move(roles);
      }
    levels.push_back(std::move(lj));
  }
  json level_secs = json::array();
  for (const auto& l : b.levels) level_secs.push_back(secs(l.seconds));
  j["timings"] = {{"read", secs(b.time.read)},
                  {"extract", secs(b.time.extract)},
                  {"preprocess", secs(b.time.preprocess)},
                  {"decompose", secs(b.time.decompose)},
                  {"levels", level_secs},
                  {"encode", secs(b.time.encode)},
                  {"check", secs(b.time.check)},
                  {"job", secs(b.time.job)},
                  {"cpu", secs(b.time.cpu)},
                  {"write", secs(b.time.write)}};
  j["timings"]["massing"] = secs(b.time.massing);
  j["sizes"] = {{"input_vertices", b.size.input_vertices},
                {"input_faces", b.size.input_faces},
                {"regions", b.size.regions},
                {"planes", b.size.planes},
                {"cells", b.size.cells},
                {"inside_cells", b.size.inside_cells},
                {"components", b.size.components},
                {"dropped_components", b.size.dropped_components},
                {"cell_closed", b.size.cell_closed},
                {"cell_manifold", b.size.cell_manifold},
                {"concave_edges", b.size.concave_edges},
                {"parts_written", b.size.parts_written},
                {"vertices_added", b.size.output_vertices_added},
                {"dropped_faces", b.size.dropped_faces},
                {"parts_repaired", b.size.parts_repaired},
                {"split_faces", b.size.split_faces}};
  int64_t nodes = 0;
  for (const auto& l : b.levels) nodes += l.nodes_expanded;
  j["nodes_expanded"] = nodes;
  j["levels"] = std::move(levels);
  j["hausdorff"] = num(b.hausdorff);
  if (!b.volume_check.method.empty() || !b.volume_check.oracle.empty())  // docs/algorithm.md §6.5
    j["volume_check"] = {
        {"estimate", num(b.volume_check.estimate)}, {"cell", num(b.volume_check.cell)},
        {"ratio", num(b.volume_check.ratio)},       {"method", b.volume_check.method},
        {"oracle", b.volume_check.oracle},          {"open_input", b.volume_check.open_input},
        {"relabelled", b.volume_check.relabelled},  {"flagged", b.volume_check.flagged},
        {"fast_path", b.volume_check.fast_path},    {"fast_path_reason", b.volume_check.fast_path_reason}};
  if (b.massing.features.valid) {  // building massing features (massing/massing.hpp)
    nlohmann::json f = nlohmann::json::object();
    add_building_attributes(f, b.massing);
    j["massing"] = json::parse(f.dump());
  }
  if (!b.problems.empty()) j["problems"] = b.problems;
  return j;
}

ReportWriter::ReportWriter(const std::string& path) : path_(path) {
  try {
    file_ = std::make_unique<mc::io::AtomicFile>(path);
  } catch (const std::exception& e) { throw mc::io::WriteError(path + ": " + e.what()); }
  spool_ = std::make_unique<mc::io::ScratchFile>(parent_dir(path));
}

ReportWriter::~ReportWriter() = default;

void ReportWriter::add(const BuildingOutcome& b) {
  spool_->append(std::string(entries_++ ? ",\n    " : "\n    ") + building_report(b).dump());
}

void ReportWriter::commit(const json& run) {
  std::ostream& o = file_->stream();
  // The run's facts, pretty-printed for people; then the building entries one per line.
  std::string head = run.dump(2);
  if (head.size() >= 2 && head.back() == '}') head.pop_back();
  while (!head.empty() && (head.back() == '\n' || head.back() == ' ')) head.pop_back();
  o << head << (run.empty() ? "" : ",") << "\n  \"buildings\": [";
  std::vector<char> buf(1 << 20);
  for (uint64_t at = 0; at < spool_->size(); at += buf.size()) {
    const size_t n = static_cast<size_t>(std::min<uint64_t>(buf.size(), spool_->size() - at));
    spool_->read_at(at, buf.data(), n);
    o.write(buf.data(), static_cast<std::streamsize>(n));
  }
  o << (entries_ ? "\n  ]\n}\n" : "]\n}\n");
  try {
    file_->commit();
  } catch (const std::exception& e) { throw mc::io::WriteError(path_ + ": " + e.what()); }
}

}  // namespace mc::report
