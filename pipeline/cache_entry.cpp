#include "pipeline/cache_entry.hpp"

#include "report/level_json.hpp"

#include <cmath>
#include <stdexcept>

namespace mc::pipeline {
using namespace mc::report;
using namespace mc::massing;

using nlohmann::json;

namespace {

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }
json num(const std::optional<double>& v) { return v ? num(*v) : json(nullptr); }

double get_num(const json& j, const char* key) {
  const json& v = j.at(key);
  if (v.is_null()) return kNaN;
  if (!v.is_number()) throw std::runtime_error(std::string("'") + key + "' is not a number");
  return v.get<double>();
}
std::optional<double> get_opt(const json& j, const char* key) {
  const json& v = j.at(key);
  if (v.is_null()) return std::nullopt;
  return get_num(j, key);
}

}  // namespace

json outcome_to_json(const BuildingOutcome& b) {
  json levels = json::array();
  for (const LevelOutcome& l : b.levels)
    levels.push_back(json::parse(level_json(l).dump()));  // report/level_json.hpp
  const Sizes& s = b.size;
  const Measures& m = b.measures;
  json centroid = nullptr;
  if (m.centroid) centroid = json::array({m.centroid->x, m.centroid->y, m.centroid->z});
  return {{"status", b.status},
          {"reason", b.reason},
          {"lod", b.lod},
          {"hausdorff", num(b.hausdorff)},
          {"volume_check",
           {{"estimate", num(b.volume_check.estimate)},
            {"cell", num(b.volume_check.cell)},
            {"ratio", num(b.volume_check.ratio)},
            {"method", b.volume_check.method},
            {"oracle", b.volume_check.oracle},
            {"open_input", b.volume_check.open_input},
            {"relabelled", b.volume_check.relabelled},
            {"flagged", b.volume_check.flagged},
            {"fast_path", b.volume_check.fast_path},
            {"fast_path_reason", b.volume_check.fast_path_reason}}},
          {"problems", b.problems},
          {"levels", std::move(levels)},
          {"sizes",
           {{"input_faces", s.input_faces},
            {"input_vertices", s.input_vertices},
            {"regions", s.regions},
            {"planes", s.planes},
            {"cells", s.cells},
            {"inside_cells", s.inside_cells},
            {"components", s.components},
            {"dropped_components", s.dropped_components},
            {"cell_closed", s.cell_closed},
            {"cell_manifold", s.cell_manifold},
            {"concave_edges", s.concave_edges},
            {"parts_written", s.parts_written},
            {"output_vertices_added", s.output_vertices_added},
            {"dropped_faces", s.dropped_faces},
            {"parts_repaired", s.parts_repaired},
            {"split_faces", s.split_faces}}},
          {"measures",
           {{"height", num(m.height)},
            {"footprint_area", num(m.footprint_area)},
            {"volume", num(m.volume)},
            {"convexity", num(m.convexity)},
            {"footprint_method", m.footprint_method},
            {"centroid", centroid},
            {"centroid_method", m.centroid_method}}},
          {"massing", massing_to_json(b.massing)}};
}

void outcome_from_json(const json& j, BuildingOutcome& b) {
  b.status = j.at("status").get<std::string>();
  b.reason = j.at("reason").get<std::string>();
  b.lod = j.at("lod").get<std::string>();
  b.hausdorff = get_num(j, "hausdorff");
  if (const auto vc = j.find("volume_check"); vc != j.end() && vc->is_object()) {  // docs/algorithm.md §6.5
    b.volume_check.estimate = get_num(*vc, "estimate");
    b.volume_check.cell = get_num(*vc, "cell");
    b.volume_check.ratio = get_num(*vc, "ratio");
    b.volume_check.method = vc->value("method", std::string());
    b.volume_check.oracle = vc->value("oracle", std::string());
    b.volume_check.open_input = vc->value("open_input", false);
    b.volume_check.relabelled = vc->value("relabelled", false);
    b.volume_check.flagged = vc->value("flagged", false);
    b.volume_check.fast_path = vc->value("fast_path", false);
    b.volume_check.fast_path_reason = vc->value("fast_path_reason", std::string());
  }
  b.problems = j.at("problems").get<std::vector<std::string>>();
  b.levels.clear();
  for (const json& lj : j.at("levels")) b.levels.push_back(level_from_json(lj));
  const json& sj = j.at("sizes");
  Sizes& s = b.size;
  s.input_faces = sj.at("input_faces").get<size_t>();
  s.input_vertices = sj.at("input_vertices").get<size_t>();
  s.regions = sj.at("regions").get<size_t>();
  s.planes = sj.at("planes").get<size_t>();
  s.cells = sj.at("cells").get<size_t>();
  s.inside_cells = sj.at("inside_cells").get<size_t>();
  s.components = sj.at("components").get<size_t>();
  s.dropped_components = sj.at("dropped_components").get<size_t>();
  s.cell_closed = sj.at("cell_closed").get<bool>();
  s.cell_manifold = sj.at("cell_manifold").get<bool>();
  s.concave_edges = sj.at("concave_edges").get<int>();
  s.parts_written = sj.at("parts_written").get<size_t>();
  s.output_vertices_added = sj.at("output_vertices_added").get<size_t>();
  s.dropped_faces = sj.at("dropped_faces").get<size_t>();
  s.parts_repaired = sj.at("parts_repaired").get<size_t>();
  s.split_faces = sj.at("split_faces").get<size_t>();
  const json& mj = j.at("measures");
  Measures& m = b.measures;
  m.height = get_opt(mj, "height");
  m.footprint_area = get_opt(mj, "footprint_area");
  m.volume = get_opt(mj, "volume");
  m.convexity = get_opt(mj, "convexity");
  m.footprint_method = mj.at("footprint_method").get<std::string>();
  const json& c = mj.at("centroid");
  if (c.is_null()) m.centroid.reset();
  else m.centroid = Vec3{c.at(0).get<double>(), c.at(1).get<double>(), c.at(2).get<double>()};
  m.centroid_method = mj.at("centroid_method").get<std::string>();
  massing_from_json(j.at("massing"), b.massing);
}

}  // namespace mc::pipeline
