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

std::string part_id(const std::string& building, size_t level, size_t index) {
  return building + "-mc" + std::to_string(level) + "-" + std::to_string(index);
}

void add_problems(std::vector<std::string>& out, const std::vector<std::string>& in) {
  for (const auto& p : in) {
    if (out.size() >= kMaxProblems) break;
    out.push_back(p);
  }
}

// Everything one written level contributes, staged before it touches the feature, so that a
// failure half-way leaves the input exactly as it was.
struct StagedPart {
  std::string id;
  json object;
};

struct LevelSource {
  const LevelResult* result = nullptr;  // null = the singleton components as parts
  std::string fallback;
};

// Which result stands in for level i (architecture.md §1: best complete result so far).
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

// One level's parts encoded and checked, not yet in the feature.
struct EncodedLevel {
  std::vector<StagedPart> staged;
  std::vector<PolygonMesh> meshes;
  LevelOutcome lv;  // the geometric fields; the search fields are the caller's
  size_t dropped_faces = 0, repaired_parts = 0, split_faces = 0;
  std::string grid_repair;  // LevelOutcome::grid_repair
  double check_seconds = 0;
  std::string defect;    // non-empty: a part fails the checks, and nothing of the level is kept
  int failed_part = -1;  // the part the defect is on
  // The parts actually encoded when slivers were merged into neighbours (output/part_merge.hpp).
  std::optional<std::vector<PartResult>> merged;
};

EncodedLevel encode_level(const std::string& building, size_t i, double threshold,
                          const std::vector<PartResult>& parts, const Preprocessed& pre,
                          const std::string& lod, const std::string& version, VertexPool& pool,
                          bool conforming, bool separate = false) {
  EncodedLevel e;
  e.lv.index = i;
  e.lv.threshold = threshold;
  e.lv.parts = parts.size();
  if (parts.empty()) {
    e.defect = "no parts";
    return e;
  }
  double total_volume = 0, largest = 0, weighted_cvx = 0, sum_cvx = 0, min_cvx = 1;
  std::vector<PolygonMesh> meshes;
  if (conforming) meshes = level_part_meshes(pre, parts);
  else
    for (const auto& part : parts) meshes.push_back(part_mesh(pre, part));
  if (separate) separate_near_touches(meshes, pool.step());
  std::vector<EncodedSolid> solids;
  for (size_t j = 0; j < parts.size(); ++j) {
    solids.push_back(encode_solid(meshes[j], lod, version, pool));
    e.check_seconds += solids.back().check_seconds;
    if (!solids.back().defect.empty()) {
      e.defect =
          "part " + std::to_string(j) + " is invalid on the output grid (" + solids.back().defect + ")";
      e.failed_part = static_cast<int>(j);
      // For a developer: the part that failed, before rounding (docs/reliability.md).
      if (const char* dir = std::getenv("MC_DUMP_GRID_DEFECTS"))
        mc::io::write_off(std::string(dir) + "/" + building + "-L" + std::to_string(i) + "-p" +
                              std::to_string(j) + (conforming ? "" : "-own") + ".off",
                          meshes[j]);
      return e;
    }
  }
  // A part repaired on its own may have changed a face it shares: both copies made the same again
  // (repairs are rare: nothing to do, and nothing copied, without one).
  const bool any_repaired =
      std::any_of(solids.begin(), solids.end(), [](const EncodedSolid& s) { return s.repaired; });
  if (conforming && any_repaired) {
    std::vector<std::vector<GridFace>> faces;
    std::vector<bool> repaired;
    for (EncodedSolid& solid : solids) {
      faces.push_back(std::move(solid.faces));
      repaired.push_back(solid.repaired);
    }
    const std::vector<size_t> changed = align_shared_faces(faces, repaired, pool.vertices());
    for (size_t k = 0; k < solids.size(); ++k) solids[k].faces = std::move(faces[k]);
    for (size_t k : changed) {
      write_solid(solids[k], meshes[k].semantic_labels, lod, version);
      solids[k].repaired = true;  // counted with the repaired parts
    }
  }
  for (size_t j = 0; j < parts.size(); ++j) {
    const PartResult& part = parts[j];
    PolygonMesh& mesh = meshes[j];
    double hull_volume = part.hull_volume;
    if (!(hull_volume > 0)) hull_volume = convex_hull(mesh.vertices).volume;  // singleton parts
    const double convexity = hull_volume > 0 ? std::min(1.0, part.volume / hull_volume) : 0.0;
    EncodedSolid& solid = solids[j];
    e.dropped_faces += solid.dropped_faces;
    e.repaired_parts += solid.repaired;
    e.split_faces += solid.split_faces;
    json neighbours = json::array();
    for (uint32_t n : part.neighbours) neighbours.push_back(part_id(building, i, n));
    const int degree = static_cast<int>(part.neighbours.size());
    e.lv.max_degree = std::max(e.lv.max_degree, degree);
    e.lv.end_parts += degree == 1;
    total_volume += part.volume;
    largest = std::max(largest, part.volume);
    weighted_cvx += convexity * part.volume;
    sum_cvx += convexity;
    min_cvx = std::min(min_cvx, convexity);
    json obj = {{"type", "BuildingPart"},
                {"parents", json::array({building})},
                {"attributes",
                 {{"morphcut_level", threshold},
                  {"morphcut_index", j},
                  {"volume", rounded(part.volume, 1e-6)},
                  {"convexity", rounded(convexity, 1e-9)},
                  {"neighbours", neighbours}}},
                {"geometry", json::array({std::move(solid.geometry)})}};
    e.staged.push_back({part_id(building, i, j), std::move(obj)});
    e.meshes.push_back(std::move(mesh));
  }
  if (total_volume > 0) e.lv.largest_share = largest / total_volume;
  e.lv.convexity = total_volume > 0 ? weighted_cvx / total_volume : 0.0;
  e.lv.mean_convexity = sum_cvx / static_cast<double>(parts.size());
  e.lv.min_convexity = min_cvx;
  return e;
}

// A level whose parts are the parts of the level encoded before it is encoded exactly as that one
// (the same meshes, vertices already in the pool, the same checks and repairs): its encoding is
// that level's under its own ids, level and neighbour ids. Most small buildings keep their parts
// over several levels (docs/benchmarks.md, "Speed").
EncodedLevel relabelled(const EncodedLevel& previous, const std::string& building, size_t i, double threshold,
                        const std::vector<PartResult>& parts) {
  EncodedLevel e = previous;
  e.lv.index = i;
  e.lv.threshold = threshold;
  e.check_seconds = 0;
  for (size_t j = 0; j < e.staged.size(); ++j) {
    e.staged[j].id = part_id(building, i, j);
    json& a = e.staged[j].object["attributes"];
    a["morphcut_level"] = threshold;
    json neighbours = json::array();
    for (uint32_t n : parts[j].neighbours) neighbours.push_back(part_id(building, i, n));
    a["neighbours"] = std::move(neighbours);
  }
  return e;
}

// A level's parts encoded on the output grid, as meshes that fit their neighbours exactly
// (level_part_meshes). When a part stays invalid after its own repairs (output/part_repair.hpp):
//   1. the level's vertices are clustered ever more coarsely (vertices within 1, 2, then 4 grid
//      steps become one) and the whole level is encoded again, so that every part sharing a
//      moved vertex moves with it;
//   2. each part is encoded from its own mesh (no vertex kept for a neighbour's corner): a kept
//      vertex rounded off its straight edge can force a sliver triangle that folds into the part.
//      Valid parts, but a neighbour's corner may then stand a fraction of a grid step inside it.
// On failure the pool is back at its mark and the first defect is reported.
EncodedLevel encode_parts_on_grid(const std::string& building, size_t i, double threshold,
                                  const std::vector<PartResult>& parts, const Preprocessed& pre,
                                  const std::string& lod, const std::string& version, VertexPool& pool) {
  const size_t mark = pool.mark();
  EncodedLevel e = encode_level(building, i, threshold, parts, pre, lod, version, pool, true);
  if (e.defect.empty()) return e;
  double spent = e.check_seconds;  // every attempt's checks count
  const std::string first = e.defect;
  const int first_part = e.failed_part;
  if (pool.can_cluster())
    for (int steps : {1, 2, 4}) {
      pool.rollback(mark);
      pool.cluster(steps, mark);
      e = encode_level(building, i, threshold, parts, pre, lod, version, pool, true);
      pool.cluster(0, 0);
      spent += e.check_seconds;
      e.check_seconds = spent;
      if (e.defect.empty()) {
        e.grid_repair = "cluster " + std::to_string(steps);
        return e;
      }
    }
  // Vertices a fraction of a step from a face of their part moved away from it (part_merge.hpp).
  pool.rollback(mark);
  e = encode_level(building, i, threshold, parts, pre, lod, version, pool, true, /*separate=*/true);
  spent += e.check_seconds;
  e.check_seconds = spent;
  if (e.defect.empty()) {
    e.grid_repair = "separated";
    return e;
  }
  pool.rollback(mark);
  e = encode_level(building, i, threshold, parts, pre, lod, version, pool, false);
  e.check_seconds += spent;
  if (e.defect.empty()) {
    e.grid_repair = "non-conforming";
    return e;
  }
  pool.rollback(mark);
  e.defect = first;
  e.failed_part = first_part;
  return e;
}

// encode_parts_on_grid, then, while a part still fails, that part merged into the neighbour it
// shares the largest face with and the level encoded again (output/part_merge.hpp): a level of
// fewer parts rather than another level. On failure the first defect is reported.
EncodedLevel encode_level_on_grid(const std::string& building, size_t i, double threshold,
                                  const std::vector<PartResult>& parts, const Preprocessed& pre,
                                  const std::string& lod, const std::string& version, VertexPool& pool) {
  EncodedLevel e = encode_parts_on_grid(building, i, threshold, parts, pre, lod, version, pool);
  if (e.defect.empty() || parts.size() < 2) return e;
  const EncodedLevel first = e;
  double spent = e.check_seconds;
  std::vector<PartResult> current = parts;
  for (size_t merges = 1; current.size() > 1 && e.failed_part >= 0; ++merges) {
    const int k = largest_neighbour(level_part_meshes(pre, current), static_cast<size_t>(e.failed_part));
    if (k < 0) break;
    current = merge_parts(current, static_cast<size_t>(e.failed_part), static_cast<size_t>(k), pre);
    e = encode_parts_on_grid(building, i, threshold, current, pre, lod, version, pool);
    spent += e.check_seconds;
    e.check_seconds = spent;
    if (e.defect.empty()) {
      e.grid_repair = "merged " + std::to_string(merges) + " part(s)" +
                      (e.grid_repair.empty() ? std::string() : ", " + e.grid_repair);
      e.merged = std::move(current);
      return e;
    }
  }
  EncodedLevel out = first;
  out.check_seconds = spent;
  return out;
}

std::string deadline_reason(const Params& p, const char* where) {
  return "deadline (timeout_s=" + fmt_seconds(p.timeout_s) + ") reached " + where;
}

// The decomposing part of the job; throws on failure (the caller turns that into "failed").
void decompose_building(BuildingOutcome& out, const mc::io::BuildingInput& in, const mc::io::Header& h,
                        const mc::WorkingFrame& frame, const Params& params, const RunConfig& rc) {
  const mc::io::Transform transform = mc::io::parse_transform(h.root, "header");
  // No vertex closer than the output grid's step (docs/algorithm.md §7.4).
  Params p = params;
  if (!in.mesh.vertices.empty())
    p.pre.output_grid = grid_step_metres(transform, frame, frame.to_file(in.mesh.vertices.front()));
  const auto start = Clock::now();
  const auto deadline =
      p.timeout_s > 0
          ? start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(p.timeout_s))
          : Clock::time_point::max();
  auto t = Clock::now();
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

  t = Clock::now();
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

  t = Clock::now();
  const std::string lod = in.lod.empty() ? std::string("2") : in.lod;
  std::vector<Vec3> new_vertices;
  VertexPool pool(new_vertices, transform, frame, p.pre.output_grid);
  std::vector<StagedPart> staged;
  std::vector<PolygonMesh> first_level_meshes;
  const std::vector<PartResult> singleton = singleton_parts(pre);
  const std::vector<PartResult>* last_good = nullptr;  // the parts of the last level written
  std::vector<std::string> notes;                      // why the result is partial
  bool fell_back = false;
  // The last level encoded, before its massing attributes, with its parts (`relabelled`).
  std::optional<std::pair<EncodedLevel, const std::vector<PartResult>*>> reusable;
  std::deque<std::vector<PartResult>> merged_levels;  // parts of levels written with merged slivers
  for (size_t i = 0; i < p.dec.levels.size(); ++i) {
    if (!writes_level(rc, i)) continue;
    const LevelSource src = source_for(dec, i);
    const std::vector<PartResult>* parts = src.result ? &src.result->parts : &singleton;
    std::string fallback = src.fallback;
    const size_t mark = pool.mark();
    const bool same_parts = reusable && *parts == *reusable->second;
    EncodedLevel e =
        same_parts ? relabelled(reusable->first, out.id, i, p.dec.levels[i], *parts)
                   : encode_level_on_grid(out.id, i, p.dec.levels[i], *parts, pre, lod, h.version, pool);
    out.time.check += e.check_seconds;
    if (!e.defect.empty()) {
      // A part that is not a valid solid (core's part mesh has a non-manifold edge) is never
      // written. Stand-ins, in order: the previous written level, a finer level (more parts,
      // but valid ones), the singleton cell. Only when none is valid does the building fail.
      pool.rollback(mark);
      const std::string why = "level " + std::to_string(i) + ": " + e.defect;
      std::vector<std::pair<const std::vector<PartResult>*, std::string>> stand_ins;
      if (last_good) stand_ins.emplace_back(last_good, "previous level");
      for (size_t k = i + 1; k < dec.levels.size(); ++k)
        stand_ins.emplace_back(&dec.levels[k].parts, "level " + std::to_string(k));
      if (parts != &singleton) stand_ins.emplace_back(&singleton, "singleton");
      std::string tried;
      for (const auto& [alt, name] : stand_ins) {
        e = encode_level_on_grid(out.id, i, p.dec.levels[i], *alt, pre, lod, h.version, pool);
        out.time.check += e.check_seconds;
        if (e.defect.empty()) {
          fallback = name;
          parts = alt;
          break;
        }
        pool.rollback(mark);
        tried += "; " + name + " too: " + e.defect;
      }
      if (!e.defect.empty()) throw std::runtime_error(why + tried);
      notes.push_back(why + ", " + fallback + " written instead");
    }
    if (e.merged) {
      merged_levels.push_back(std::move(*e.merged));
      e.merged.reset();
      parts = &merged_levels.back();
    }
    LevelOutcome& lv = e.lv;
    lv.fallback = fallback;
    fell_back = fell_back || !fallback.empty();
    if (src.result && fallback.empty() && parts == &src.result->parts) {
      const LevelResult& r = *src.result;
      lv.convexity = r.convexity;
      lv.mean_convexity = r.mean_convexity;
      lv.min_convexity = r.min_convexity;
      lv.cost = r.cost, lv.g = r.g, lv.h = r.h;
      lv.remaining_concave = r.remaining_concave;
      lv.nodes_expanded = r.nodes_expanded;
      lv.seconds = r.seconds;
      lv.truncated = r.truncated;
    }
    out.size.dropped_faces += e.dropped_faces;
    out.size.parts_repaired += e.repaired_parts;
    out.size.split_faces += e.split_faces;
    lv.grid_repair = e.grid_repair;
    if (fallback.empty() && e.grid_repair.empty()) reusable.emplace(e, parts);
    else reusable.reset();
    {  // massing analytics (massing/massing.hpp, docs/massing.md): roles and contacts as part attributes
      const auto tm = Clock::now();
      const bool own = e.grid_repair == "non-conforming";  // those meshes carry no neighbours
      std::vector<PolygonMesh> own_meshes;
      if (own) own_meshes = level_part_meshes(pre, *parts);
      LevelMassing lm = analyse_level(own ? own_meshes : e.meshes, *parts, i, p.dec.levels[i], p.massing);
      for (size_t j = 0; j < e.staged.size() && j < lm.parts.size(); ++j)
        add_part_attributes(attributes_of(e.staged[j].object), lm, j, out.id);
      out.massing.levels.push_back(std::move(lm));
      out.time.massing += since(tm);
    }
    for (auto& s : e.staged) staged.push_back(std::move(s));
    if (first_level_meshes.empty()) first_level_meshes = std::move(e.meshes);
    out.levels.push_back(std::move(lv));
    last_good = parts;
  }

  const auto tm = Clock::now();
  finish_massing(out.massing, p.massing);  // building features at the analysis level
  out.time.massing += since(tm);

  // Whole building: volume, convexity against the hull of all part vertices (= the singleton's
  // hull, every singleton vertex being a part vertex), volume centroid.
  double volume = 0;
  for (const auto& c : pre.components) volume += c.volume;
  out.measures.volume = volume;
  std::vector<Vec3> all_points;
  for (const auto& m : first_level_meshes)
    all_points.insert(all_points.end(), m.vertices.begin(), m.vertices.end());
  const double hull = convex_hull(all_points).volume;
  if (hull > 0) out.measures.convexity = std::min(1.0, volume / hull);
  const VolumeCentroid vc = volume_centroid(first_level_meshes);
  if (vc.volume > 0) {
    out.measures.centroid = frame.to_file(vc.centroid);
    out.measures.centroid_method = "solid";
  }
  to_file(out.massing, frame);  // the footprints' coordinates, for the GeoPackage

  // Commit: nothing below throws on valid JSON objects.
  for (const auto& s : staged)
    if (out.feature.objects.contains(s.id)) throw std::runtime_error("object id " + s.id + " already exists");
  const int64_t base = static_cast<int64_t>(out.feature.vertices.size());
  for (auto& s : staged) {
    auto& geom = s.object["geometry"][0]["boundaries"];
    for (auto& shell : geom)
      for (auto& surface : shell)
        for (auto& ring : surface)
          for (auto& v : ring) v = v.get<int64_t>() + base;
  }
  out.feature.vertices.insert(out.feature.vertices.end(), new_vertices.begin(), new_vertices.end());
  json& building = out.feature.objects[out.id];
  if (!building.contains("children") || !building["children"].is_array())
    building["children"] = json::array();
  for (auto& s : staged) {
    building["children"].push_back(s.id);
    out.feature.objects[s.id] = std::move(s.object);
  }
  out.size.parts_written = staged.size();
  out.size.output_vertices_added = new_vertices.size();
  out.time.encode = since(t);

  if (dec.partial || pre.truncated || fell_back) {
    out.status = "partial";
    if (!dec.reason.empty()) notes.insert(notes.begin(), dec.reason);
    else if (pre.truncated) notes.insert(notes.begin(), deadline_reason(p, "during preprocessing"));
    else if (dec.partial || notes.empty())
      notes.insert(notes.begin(), deadline_reason(p, "before the last level"));
    for (const auto& n : notes) out.reason += (out.reason.empty() ? "" : "; ") + n;
  } else {
    out.status = "ok";
  }
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
