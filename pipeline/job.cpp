#include "pipeline/job.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <chrono>
#include <cmath>
#include <exception>
#include <sstream>

#include "core/decompose.hpp"
#include "core/hull.hpp"
#include "core/preprocess.hpp"
#include "io/cityjson_building.hpp"
#include "io/cityjson_common.hpp"
#include "io/off_obj.hpp"
#include "output/level_views.hpp"
#include "pipeline/level_writer.hpp"
#include "massing/massing.hpp"
#include "pipeline/measures.hpp"
#include "output/output_grid.hpp"
#include "output/part_merge.hpp"
#include "output/part_objects.hpp"
#include "output/part_repair.hpp"
#include "output/rounding.hpp"
#include "pipeline/terrain.hpp"

namespace mc::pipeline {
using namespace mc::report;

using namespace mc::massing;
using namespace mc::output;

using nlohmann::json;

namespace {

constexpr size_t kMaxProblems = 20;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

void add_problems(std::vector<std::string>& out, const std::vector<std::string>& in) {
  for (const auto& p : in) {
    if (out.size() >= kMaxProblems) break;
    out.push_back(p);
  }
}

std::string fmt_seconds(double s) {
  std::ostringstream o;
  o << s;
  return o.str();
}

std::string lods_text(const std::vector<std::string>& lods) {
  std::string s;
  for (const auto& l : lods) s += (s.empty() ? "" : ", ") + l;
  return s.empty() ? "none" : s;
}

json& attributes_of(json& obj) {
  if (!obj.contains("attributes") || !obj["attributes"].is_object()) obj["attributes"] = json::object();
  return obj["attributes"];
}

void set_status_attributes(BuildingOutcome& out) {
  auto it = out.feature.objects.find(out.id);
  if (it == out.feature.objects.end() || !it->is_object()) return;
  json& a = attributes_of(*it);
  a["morphcut_status"] = out.status;
  if (!out.reason.empty()) a["morphcut_reason"] = out.reason;
  if (!out.levels.empty()) {
    json parts = json::array(), levels = json::array();
    for (const auto& l : out.levels) {
      parts.push_back(l.parts);
      levels.push_back(l.threshold);
    }
    a["morphcut_parts"] = parts;
    a["morphcut_levels"] = levels;
  }
  if (std::isfinite(out.hausdorff)) a["morphcut_hausdorff"] = rounded(out.hausdorff, 1e-6);
  // What every level's parts must add up to (checked by `morphcut-city validate`).
  if (!out.levels.empty() && out.measures.volume)
    a["morphcut_cell_volume"] = rounded(*out.measures.volume, 1e-6);
  // A cell whose volume disagrees with the independent estimate beyond preprocess.volume_check,
  // after a second labelling: the status stays, the disagreement is on the Building
  // (docs/algorithm.md §6.5, docs/output-format.md).
  if (out.volume_check.flagged && !out.levels.empty())
    a["morphcut_volume_check"] = {{"estimate", rounded(out.volume_check.estimate, 1e-3)},
                                  {"cell", rounded(out.volume_check.cell, 1e-3)},
                                  {"ratio", rounded(out.volume_check.ratio, 1e-4)},
                                  {"method", out.volume_check.method},
                                  {"oracle", out.volume_check.oracle}};
  add_building_attributes(a, out.massing);  // massing features (docs/massing.md)
}

std::string deadline_reason(const Params& p, const char* where) {
  return "deadline (timeout_s=" + fmt_seconds(p.timeout_s) + ") reached " + where;
}

// The building's parameters: the output grid's step near it (docs/algorithm.md §7.4), and the
// fidelity's maxima only (the outputs carry no mean distance).
Params building_params(const Params& params, const mc::io::Header& h, const WorkingFrame& frame,
                       const PolygonMesh& mesh) {
  Params p = params;
  p.pre.mean_distances = false;
  if (!mesh.vertices.empty())
    p.pre.output_grid = grid_step_metres(mc::io::parse_transform(h.root, "header"), frame,
                                         frame.to_file(mesh.vertices.front()));
  return p;
}

Clock::time_point deadline_of(const Params& p) {
  return p.timeout_s > 0
             ? Clock::now() +
                   std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(p.timeout_s))
             : Clock::time_point::max();
}

// The singleton cell (docs/algorithm.md §2–§8), its sizes and volume check into the outcome.
Preprocessed preprocess_building(BuildingOutcome& out, const mc::io::BuildingInput& in,
                                 const mc::io::Header& h, const Params& p, Clock::time_point deadline) {
  const auto t = Clock::now();
  Preprocessed pre;
  try {
    // (terrain: pipeline/terrain.hpp; the fidelity measure runs beside the levels)
    const double terrain = terrain_height(out.feature) * h.coords.vertical_unit;  // metres
    pre = preprocess(in.mesh, p.pre, deadline, terrain, /*defer_fidelity=*/true);
  } catch (const std::exception& e) {
    // Carving cut short by the deadline finds no inside cell: the deadline is the reason.
    if (Clock::now() >= deadline)
      throw std::runtime_error(deadline_reason(p, "during preprocessing") + " (" + e.what() + ")");
    throw;
  }
  out.time.preprocess = since(t);
  out.size.input_faces = pre.input_faces;
  out.size.regions = pre.regions;
  out.size.planes = pre.planes->size();
  out.size.cells = pre.cells;
  out.size.inside_cells = pre.inside_cells;
  out.size.components = pre.components.size();
  out.size.dropped_components = pre.dropped_components;
  out.size.cell_closed = pre.closed;
  out.size.cell_manifold = pre.manifold;
  {  // the singleton cell's volume check (docs/algorithm.md §6.5)
    const mc::VolumeCheck& v = pre.volume_check;
    auto& o = out.volume_check;
    if (v.estimate > 0) {
      o.estimate = v.estimate;
      o.ratio = v.ratio;
      o.method = v.method;
    }
    o.cell = v.cell;
    o.oracle = v.oracle;
    o.open_input = pre.open_input;
    o.relabelled = v.relabelled;
    o.flagged = v.flagged;
    o.fast_path = pre.fast_path;
    o.fast_path_reason = pre.fast_path_reason;
  }
  add_problems(out.problems, pre.problems);
  if (pre.components.empty()) throw std::runtime_error("preprocessing produced no interior cells");
  return pre;
}

// The levels (docs/algorithm.md §9–§14), with the fidelity measure beside them.
Decomposition decompose_levels(BuildingOutcome& out, Preprocessed& pre, const Params& p,
                               Clock::time_point deadline) {
  const auto t = Clock::now();
  Decomposition dec;
  try {
    dec = decompose_measuring_fidelity(pre, p.dec, deadline);
  } catch (...) {
    if (pre.hausdorff >= 0) out.hausdorff = pre.hausdorff;  // measured even when the levels fail
    throw;
  }
  out.time.decompose = since(t);
  if (pre.hausdorff >= 0) out.hausdorff = pre.hausdorff;
  out.size.concave_edges = dec.concave_edges;
  return dec;
}

// Roles and contacts of a written level's parts as their attributes (massing/massing.hpp,
// docs/massing.md).
void analyse_massing(BuildingOutcome& out, WrittenLevel& w, const Preprocessed& pre, size_t i,
                     const Params& p) {
  const auto tm = Clock::now();
  const bool own = w.e.grid_repair == "non-conforming";  // those meshes carry no neighbours
  std::vector<PolygonMesh> own_meshes;
  if (own) own_meshes = level_part_meshes(pre, *w.parts);
  LevelMassing lm = analyse_level(own ? own_meshes : w.e.meshes, *w.parts, i, p.dec.levels[i], p.massing);
  for (size_t j = 0; j < w.e.staged.size() && j < lm.parts.size(); ++j)
    add_part_attributes(attributes_of(w.e.staged[j].object), lm, j, out.id);
  out.massing.levels.push_back(std::move(lm));
  out.time.massing += since(tm);
}

// Whole building: volume, convexity against the hull of all part vertices (= the singleton's
// hull, every singleton vertex being a part vertex), volume centroid; the massing footprints in
// the file's coordinates.
void measure_building(BuildingOutcome& out, const Preprocessed& pre,
                      const std::vector<PolygonMesh>& first_level, const WorkingFrame& frame) {
  double volume = 0;
  for (const auto& c : pre.components) volume += c.volume;
  out.measures.volume = volume;
  std::vector<Vec3> all_points;
  for (const auto& m : first_level) all_points.insert(all_points.end(), m.vertices.begin(), m.vertices.end());
  const double hull = convex_hull(all_points).volume;
  if (hull > 0) out.measures.convexity = std::min(1.0, volume / hull);
  const VolumeCentroid vc = volume_centroid(first_level);
  if (vc.volume > 0) {
    out.measures.centroid = frame.to_file(vc.centroid);
    out.measures.centroid_method = "solid";
  }
  to_file(out.massing, frame);  // the footprints' coordinates, for the GeoPackage
}

// ok, or partial with every reason: the deadline, a level that fell back.
void set_status(BuildingOutcome& out, const Decomposition& dec, const Preprocessed& pre,
                std::vector<std::string> notes, bool fell_back, const Params& p) {
  if (!(dec.partial || pre.truncated || fell_back)) {
    out.status = "ok";
    return;
  }
  out.status = "partial";
  if (!dec.reason.empty()) notes.insert(notes.begin(), dec.reason);
  else if (pre.truncated) notes.insert(notes.begin(), deadline_reason(p, "during preprocessing"));
  else if (dec.partial || notes.empty())
    notes.insert(notes.begin(), deadline_reason(p, "before the last level"));
  for (const auto& n : notes) out.reason += (out.reason.empty() ? "" : "; ") + n;
}

// The decomposing part of the job; throws on failure (the caller turns that into "failed").
void decompose_building(BuildingOutcome& out, const mc::io::BuildingInput& in, const mc::io::Header& h,
                        const WorkingFrame& frame, const Params& params, const RunConfig& rc) {
  const Params p = building_params(params, h, frame, in.mesh);
  const auto deadline = deadline_of(p);
  Preprocessed pre = preprocess_building(out, in, h, p, deadline);
  const Decomposition dec = decompose_levels(out, pre, p, deadline);
  const auto t = Clock::now();
  LevelWriter writer(out.id, pre, dec, p.dec.levels, in.lod.empty() ? std::string("2") : in.lod, h.version,
                     mc::io::parse_transform(h.root, "header"), frame, p.pre.output_grid);
  for (size_t i = 0; i < p.dec.levels.size(); ++i) {
    if (!writes_level(rc, i)) continue;
    WrittenLevel w = writer.encode(i, out.time.check);
    analyse_massing(out, w, pre, i, p);
    out.levels.push_back(writer.keep(std::move(w), out));
  }
  const auto tm = Clock::now();
  finish_massing(out.massing, p.massing);  // building features at the analysis level
  out.time.massing += since(tm);
  measure_building(out, pre, writer.first_level_meshes(), frame);
  writer.commit(out);
  out.time.encode = since(t);
  set_status(out, dec, pre, writer.notes(), writer.fell_back(), p);
}

}  // namespace

BuildingOutcome failed_building(mc::io::Feature&& f, const std::string& reason) {
  BuildingOutcome out;
  out.id = f.id;
  out.is_building = mc::io::is_building(f);
  out.feature = std::move(f);
  out.status = "failed";
  out.reason = reason;
  if (out.is_building) set_status_attributes(out);
  return out;
}

BuildingOutcome run_building(const mc::io::Feature& f, const mc::io::Header& h, const Params& p,
                             const RunConfig& rc) {
  return run_building(mc::io::Feature(f), h, p, rc);
}

BuildingOutcome run_building(mc::io::Feature&& f, const mc::io::Header& h, const Params& p,
                             const RunConfig& rc) {
  const auto start = Clock::now();
  BuildingOutcome out;
  out.id = f.id;
  if (std::getenv("MC_TRACE")) std::fprintf(stderr, "start %s\n", f.id.c_str());
  out.is_building = mc::io::is_building(f);
  out.feature = std::move(f);
  if (!out.is_building) return out;
  try {
    strip_previous_parts(out.feature);
    auto t = Clock::now();
    mc::io::BuildingInput in = mc::io::extract_building(out.feature, h, rc.lod);
    // Metres from here on, whatever the file's CRS (docs/algorithm.md §2.1).
    const mc::WorkingFrame frame(h.coords, in.mesh.vertices);
    if (frame.swapped())
      in.problems.push_back(
          "latitude and longitude are read in the other axis order: the declared order puts "
          "latitudes out of range");
    frame.to_metric(in.mesh);
    out.time.extract = since(t);
    out.lod = in.lod;
    add_problems(out.problems, in.problems);
    out.size.input_vertices = in.mesh.vertices.size();
    out.size.input_faces = in.mesh.faces.size();
    if (in.mesh.empty()) {
      out.status = "skipped";
      out.reason = rc.lod == "highest"
                       ? "no surface geometry"
                       : "no surface geometry at LoD " + rc.lod +
                             " (available: " + lods_text(mc::io::building_lods(out.feature, h)) + ")";
      if (!in.problems.empty()) out.reason += "; " + in.problems.front();
    } else if (p.max_faces > 0 && in.mesh.faces.size() > static_cast<size_t>(p.max_faces)) {
      out.status = "skipped";
      out.reason = "too large: " + std::to_string(in.mesh.faces.size()) + " faces > max_faces (" +
                   std::to_string(p.max_faces) + ")";
    } else {
      out.measures.height = height(in.mesh);
      const Footprint fp = footprint(in.mesh);
      out.measures.footprint_area = fp.area;
      out.measures.footprint_method = fp.method;
      if (auto c = bbox_centre(in.mesh)) {
        out.measures.centroid = frame.to_file(*c);
        out.measures.centroid_method = "bbox";
      }
      decompose_building(out, in, h, frame, p, rc);
    }
  } catch (const std::exception& e) {
    out.status = "failed";
    out.reason = e.what();
  } catch (...) {
    out.status = "failed";
    out.reason = "unknown exception";
  }
  if (out.status == "failed") {
    out.levels.clear();
    out.massing = {};
    out.size.parts_written = 0;
  }
  set_status_attributes(out);
  out.time.job = since(start);
  return out;
}

}  // namespace mc::pipeline
