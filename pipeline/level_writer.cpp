#include "pipeline/level_writer.hpp"

#include <stdexcept>

namespace mc::pipeline {

using namespace mc::report;
using nlohmann::json;

namespace {

struct LevelSource {
  const LevelResult* result = nullptr;  // null = the singleton components as parts
  std::string fallback;
};

// Which result stands in for level i: the best complete result so far.
LevelSource source_for(const Decomposition& d, size_t i) {
  if (i < d.levels.size()) return {&d.levels[i], ""};
  if (!d.levels.empty()) return {&d.levels.back(), "previous level"};
  return {nullptr, "singleton"};
}

std::vector<PartResult> singleton_parts(const Preprocessed& pre) {
  std::vector<PartResult> parts;
  for (size_t c = 0; c < pre.components.size(); ++c) {
    PartResult r;
    r.cells = pre.components[c].cells;
    r.volume = pre.components[c].volume;
    r.component = static_cast<int>(c);
    parts.push_back(std::move(r));
  }
  return parts;
}

}  // namespace

LevelWriter::LevelWriter(const std::string& building, const Preprocessed& pre, const Decomposition& dec,
                         const std::vector<double>& thresholds, const std::string& lod,
                         const std::string& version, const mc::io::Transform& transform,
                         const WorkingFrame& frame, double grid_step)
    : building_(building),
      pre_(pre),
      dec_(dec),
      thresholds_(thresholds),
      lod_(lod),
      version_(version),
      pool_(new_vertices_, transform, frame, grid_step),
      singleton_(singleton_parts(pre)) {}

WrittenLevel LevelWriter::encode(size_t i, double& check_seconds) {
  const LevelSource src = source_for(dec_, i);
  WrittenLevel w;
  w.parts = src.result ? &src.result->parts : &singleton_;
  w.fallback = src.fallback;
  const size_t mark = pool_.mark();
  const bool same_parts = reusable_ && *w.parts == *reusable_->second;
  w.e = same_parts
            ? relabelled(reusable_->first, building_, i, thresholds_[i], *w.parts)
            : encode_level_on_grid(building_, i, thresholds_[i], *w.parts, pre_, lod_, version_, pool_);
  check_seconds += w.e.check_seconds;
  if (!w.e.defect.empty()) {
    // A part that is not a valid solid (core's part mesh has a non-manifold edge) is never
    // written. Stand-ins, in order: the previous written level, a finer level (more parts,
    // but valid ones), the singleton cell. Only when none is valid does the building fail.
    pool_.rollback(mark);
    const std::string why = "level " + std::to_string(i) + ": " + w.e.defect;
    std::vector<std::pair<const std::vector<PartResult>*, std::string>> stand_ins;
    if (last_good_) stand_ins.emplace_back(last_good_, "previous level");
    for (size_t k = i + 1; k < dec_.levels.size(); ++k)
      stand_ins.emplace_back(&dec_.levels[k].parts, "level " + std::to_string(k));
    if (w.parts != &singleton_) stand_ins.emplace_back(&singleton_, "singleton");
    std::string tried;
    for (const auto& [alt, name] : stand_ins) {
      w.e = encode_level_on_grid(building_, i, thresholds_[i], *alt, pre_, lod_, version_, pool_);
      check_seconds += w.e.check_seconds;
      if (w.e.defect.empty()) {
        w.fallback = name;
        w.parts = alt;
        break;
      }
      pool_.rollback(mark);
      tried += "; " + name + " too: " + w.e.defect;
    }
    if (!w.e.defect.empty()) throw std::runtime_error(why + tried);
    notes_.push_back(why + ", " + w.fallback + " written instead");
  }
  if (w.e.merged) {
    merged_levels_.push_back(std::move(*w.e.merged));
    w.e.merged.reset();
    w.parts = &merged_levels_.back();
  }
  w.e.lv.fallback = w.fallback;
  fell_back_ = fell_back_ || !w.fallback.empty();
  if (const LevelResult* r = source_for(dec_, i).result; r && w.fallback.empty() && w.parts == &r->parts) {
    LevelOutcome& lv = w.e.lv;
    lv.convexity = r->convexity;
    lv.mean_convexity = r->mean_convexity;
    lv.min_convexity = r->min_convexity;
    lv.cost = r->cost, lv.g = r->g, lv.h = r->h;
    lv.remaining_concave = r->remaining_concave;
    lv.nodes_expanded = r->nodes_expanded;
    lv.seconds = r->seconds;
    lv.truncated = r->truncated;
  }
  w.e.lv.grid_repair = w.e.grid_repair;
  if (w.fallback.empty() && w.e.grid_repair.empty()) reusable_.emplace(w.e, w.parts);
  else reusable_.reset();
  return w;
}

LevelOutcome LevelWriter::keep(WrittenLevel&& w, BuildingOutcome& out) {
  out.size.dropped_faces += w.e.dropped_faces;
  out.size.parts_repaired += w.e.repaired_parts;
  out.size.split_faces += w.e.split_faces;
  for (auto& s : w.e.staged) staged_.push_back(std::move(s));
  if (first_level_meshes_.empty()) first_level_meshes_ = std::move(w.e.meshes);
  last_good_ = w.parts;
  return std::move(w.e.lv);
}

void LevelWriter::commit(BuildingOutcome& out) {
  // Nothing below throws on valid JSON objects.
  for (const auto& s : staged_)
    if (out.feature.objects.contains(s.id)) throw std::runtime_error("object id " + s.id + " already exists");
  const int64_t base = static_cast<int64_t>(out.feature.vertices.size());
  for (auto& s : staged_) {
    auto& geom = s.object["geometry"][0]["boundaries"];
    for (auto& shell : geom)
      for (auto& surface : shell)
        for (auto& ring : surface)
          for (auto& v : ring) v = v.get<int64_t>() + base;
  }
  out.feature.vertices.insert(out.feature.vertices.end(), new_vertices_.begin(), new_vertices_.end());
  json& building = out.feature.objects[out.id];
  if (!building.contains("children") || !building["children"].is_array())
    building["children"] = json::array();
  for (auto& s : staged_) {
    building["children"].push_back(s.id);
    out.feature.objects[s.id] = std::move(s.object);
  }
  out.size.parts_written = staged_.size();
  out.size.output_vertices_added = new_vertices_.size();
}

}  // namespace mc::pipeline
