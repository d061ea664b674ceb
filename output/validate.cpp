#include "output/validate.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <unordered_map>

#include "core/solid_validation.hpp"
#include "io/cityjson_building.hpp"
#include "io/cityjson_common.hpp"
#include "io/cityjson_reader.hpp"
#include "output/output_grid.hpp"

namespace mc::output {

using nlohmann::json;
namespace vc = validate_code;

const char* validate_error_name(int code) {
  switch (code) {
    case vc::kPartsOverlap:
      return "BUILDINGPARTS_OVERLAP";
    case vc::kPartsVolumeMismatch:
      return "PARTS_VOLUME_MISMATCH";
    case vc::kLevelsVolumeMismatch:
      return "LEVELS_VOLUME_MISMATCH";
    case vc::kPartCountMismatch:
      return "PART_COUNT_MISMATCH";
    case vc::kOverlapNotComputed:
      return "OVERLAP_NOT_COMPUTED";
    case vc::kPartsStatusMismatch:
      return "PARTS_STATUS_MISMATCH";
    case vc::kReadProblem:
      return "READ_PROBLEM";
    case vc::kParentsChildren:
      return "PARENTS_CHILDREN_INCONSISTENT";
    case vc::kInvalidObject:
      return "INVALID_CITYOBJECT";
    default:
      return solid_error_name(code);
  }
}

namespace {

std::string num(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

void add(ObjectReport& r, int code, std::string message) {
  r.errors.push_back({code, validate_error_name(code), std::move(message)});
}

bool is_our_part(const json& obj) {
  if (!obj.is_object() || obj.value("type", "") != "BuildingPart") return false;
  auto a = obj.find("attributes");
  return a != obj.end() && a->is_object() && a->contains("morphcut_level") &&
         (*a)["morphcut_level"].is_number();
}

std::vector<std::string> string_list(const json& obj, const char* key) {
  std::vector<std::string> out;
  auto it = obj.find(key);
  if (it == obj.end() || !it->is_array()) return out;
  for (const auto& v : *it)
    if (v.is_string()) out.push_back(v.get<std::string>());
  return out;
}

bool lists(const json& obj, const char* key, const std::string& id) {
  const auto l = string_list(obj, key);
  return std::find(l.begin(), l.end(), id) != l.end();
}

// Members every CityObject needs and the mirror rule of "parents"/"children" (within the feature:
// the reader groups a feature by exactly these links, so a partner outside it does not exist).
void check_structure(const std::string& id, const json& obj, const json& objects, ObjectReport& r) {
  if (!obj.is_object()) {
    add(r, vc::kInvalidObject, "not a JSON object");
    return;
  }
  if (!obj.contains("type") || !obj["type"].is_string()) add(r, vc::kInvalidObject, "no \"type\" string");
  if (obj.contains("geometry")) {
    if (!obj["geometry"].is_array()) add(r, vc::kInvalidObject, "\"geometry\" is not an array");
    else
      for (size_t g = 0; g < obj["geometry"].size(); ++g) {
        const json& geom = obj["geometry"][g];
        if (!geom.is_object() || !geom.contains("type") ||
            !(geom.contains("boundaries") || geom.contains("template")))
          add(r, vc::kInvalidObject, "geometry #" + std::to_string(g) + " lacks \"type\" or \"boundaries\"");
      }
  }
  for (const auto& c : string_list(obj, "children"))
    if (auto it = objects.find(c); it != objects.end() && it->is_object() && !lists(*it, "parents", id))
      add(r, vc::kParentsChildren, "child \"" + c + "\" does not list it among its parents");
  for (const auto& p : string_list(obj, "parents"))
    if (auto it = objects.find(p); it != objects.end() && it->is_object() && !lists(*it, "children", id))
      add(r, vc::kParentsChildren, "parent \"" + p + "\" does not list it among its children");
}

// A part's Solid as a polygon mesh over the feature's vertices; empty with an error when the
// geometry is not one Solid with one shell.
PolygonMesh part_solid(const json& obj, const std::vector<Vec3>& vertices, ObjectReport& r) {
  PolygonMesh m;
  const json* geoms = obj.contains("geometry") && obj["geometry"].is_array() ? &obj["geometry"] : nullptr;
  if (!geoms || geoms->size() != 1 || !(*geoms)[0].is_object() || (*geoms)[0].value("type", "") != "Solid") {
    add(r, vc::kInvalidObject, "a morphcut part must have exactly one Solid geometry");
    return m;
  }
  const json& g = (*geoms)[0];
  static const json kNone;
  const json& b = g.contains("boundaries") ? g["boundaries"] : kNone;
  if (!b.is_array() || b.size() != 1 || !b[0].is_array() || b[0].empty()) {
    add(r, vc::kInvalidObject, "the Solid must have exactly one non-empty shell");
    return m;
  }
  if (!g.contains("lod")) add(r, vc::kInvalidObject, "the Solid has no \"lod\"");
  if (g.contains("semantics")) {
    const json& s = g["semantics"];
    const bool ok = s.is_object() && s.contains("values") && s["values"].is_array() &&
                    s["values"].size() == 1 && s["values"][0].is_array() &&
                    s["values"][0].size() == b[0].size();
    if (!ok) add(r, vc::kInvalidObject, "semantics \"values\" do not match the shell's surfaces");
  }
  std::unordered_map<int64_t, uint32_t> local;
  bool bad_ref = false;
  for (const auto& surface : b[0]) {
    Polygon poly;
    if (!surface.is_array()) continue;
    for (const auto& ring : surface) {
      std::vector<uint32_t> out;
      if (ring.is_array())
        for (const auto& v : ring) {
          const int64_t i = v.is_number_integer() ? v.get<int64_t>() : -1;
          if (i < 0 || static_cast<size_t>(i) >= vertices.size()) {
            bad_ref = true;
            continue;
          }
          auto [it, fresh] = local.try_emplace(i, static_cast<uint32_t>(m.vertices.size()));
          if (fresh) m.vertices.push_back(vertices[static_cast<size_t>(i)]);
          out.push_back(it->second);
        }
      poly.rings.push_back(std::move(out));
    }
    m.faces.push_back(std::move(poly));
  }
  if (bad_ref)
    add(r, vc::kInvalidObject, "the Solid refers to vertices that do not exist (dropped before checking)");
  return m;
}

struct Part {
  std::string id;
  double level = 0;
  SolidCheck check;
  ObjectReport report;
};

// Convex hulls apart (one hull facet plane has the other part on its outer side, within
// `tol`): the parts cannot share volume, no exact computation needed.
bool hulls_separated(const SolidCheck& a, const SolidCheck& b, double tol) {
  for (int axis = 0; axis < 3; ++axis)
    if (a.box.hi[axis] < b.box.lo[axis] + tol || b.box.hi[axis] < a.box.lo[axis] + tol) return true;
  auto outside = [tol](const SolidCheck& hull, const SolidCheck& other) {
    for (const Plane& p : hull.hull_facets) {
      bool all = true;
      for (const Vec3& v : other.shell.points)
        if (p.signed_distance(v) < -tol) {
          all = false;
          break;
        }
      if (all) return true;
    }
    return false;
  };
  return outside(a, b) || outside(b, a);
}

// Worst-case volume change of solids of total surface `area` whose vertices were each rounded to
// a grid of step `scale` (a vertex moves at most half a grid diagonal along the face normal).
double quantisation_bound(double area, double scale) { return area * scale * std::sqrt(3.0) / 2; }

std::optional<double> number_attribute(const json& obj, const char* key) {
  auto a = obj.find("attributes");
  if (a == obj.end() || !a->is_object()) return std::nullopt;
  auto v = a->find(key);
  if (v == a->end() || !v->is_number()) return std::nullopt;
  return v->get<double>();
}

// Tiling of one building: counts per level, overlaps, volume sums.
// The part counts the Building declares (morphcut_levels / morphcut_parts) against the parts the
// file holds. A level output (docs/output-format.md) shows one level, named by the Building's
// `morphcut_level`; a file without it holds every level's parts.
void check_part_counts(ObjectReport& building, const json& bobj, const std::vector<double>& levels,
                       const std::map<double, std::vector<size_t>>& by_level) {
  const json& attrs = bobj.contains("attributes") ? bobj["attributes"] : json::object();
  if (attrs.contains("morphcut_levels") && attrs.contains("morphcut_parts") &&
      attrs["morphcut_levels"].is_array() && attrs["morphcut_parts"].is_array() &&
      attrs["morphcut_levels"].size() == attrs["morphcut_parts"].size()) {
    const std::optional<double> shown = number_attribute(bobj, "morphcut_level");
    std::vector<double> declared;
    for (size_t l = 0; l < attrs["morphcut_levels"].size(); ++l) {
      const double t =
          attrs["morphcut_levels"][l].is_number() ? attrs["morphcut_levels"][l].get<double>() : NAN;
      if (shown && t != *shown) continue;
      declared.push_back(t);
      const size_t want =
          attrs["morphcut_parts"][l].is_number_unsigned() ? attrs["morphcut_parts"][l].get<size_t>() : 0;
      const size_t have = by_level.count(t) ? by_level.at(t).size() : 0;
      if (want != have)
        add(building, vc::kPartCountMismatch,
            "level " + num(t) + ": morphcut_parts says " + std::to_string(want) + ", the file has " +
                std::to_string(have) + " parts");
    }
    for (double t : levels)
      if (std::find(declared.begin(), declared.end(), t) == declared.end())
        add(building, vc::kPartCountMismatch,
            "parts of level " + num(t) + ", which morphcut_levels does not list");
  } else {
    add(building, vc::kPartCountMismatch, "morphcut_levels / morphcut_parts missing or of different lengths");
  }
}

// Overlaps at one level: every pair of valid parts, as val3dity tests them (exact), or with a
// volume tolerance when one is given.
void check_overlaps(ObjectReport& building, std::vector<Part>& parts, const std::vector<size_t>& idx,
                    double t, double scale, const ValidateOptions& opt, ValidationCounts& counts) {
  for (size_t a = 0; a < idx.size(); ++a)
    for (size_t b = a + 1; b < idx.size(); ++b) {
      Part &pa = parts[idx[a]], &pb = parts[idx[b]];
      if (!pa.check.closed_manifold || !pb.check.closed_manifold) continue;
      std::optional<Common> common;
      double tol = 0;
      if (opt.overlap <= 0) {
        if (!interiors_overlap(pa.check.shell, pb.check.shell, &counts.overlap_tests)) continue;
        common = common_volume(pa.check.shell, pb.check.shell);
        if (!common) common = Common{};  // the exact test found it; its size is unknown
      } else {
        // Apart by more than the 1 mm output grid: no common volume to compute.
        if (hulls_separated(pa.check, pb.check, 1e-3)) continue;
        ++counts.overlap_tests;
        common = common_volume(pa.check.shell, pb.check.shell);
        // Touching parts share faces whose vertices were rounded to the grid independently of
        // how each part triangulates them: slivers up to the quantisation bound of the contact
        // (at most the smaller surface) are touching, not overlap.
        tol = opt.overlap + quantisation_bound(std::min(pa.check.area, pb.check.area), scale);
        if (!common) {
          add(building, vc::kOverlapNotComputed,
              "level " + num(t) + ": the common volume of " + pa.id + " and " + pb.id +
                  " could not be computed exactly");
          continue;
        }
        if (common->volume <= tol) continue;
      }
      const std::string what =
          " m³ in common" +
          (common->area > 0 ? ", " + num(2 * common->volume / common->area) + " m thick on average" : "") +
          (opt.overlap > 0 ? " (tolerance " + num(tol) + " m³)" : " (exact test)");
      add(pa.report, vc::kPartsOverlap, "overlaps " + pb.id + ": " + num(common->volume) + what);
      add(pb.report, vc::kPartsOverlap, "overlaps " + pa.id + ": " + num(common->volume) + what);
    }
}

void check_tiling(ObjectReport& building, const json& bobj, std::vector<Part>& parts, double scale,
                  const ValidateOptions& opt, ValidationCounts& counts) {
  std::vector<double> levels;  // in first-seen order
  std::map<double, std::vector<size_t>> by_level;
  for (size_t i = 0; i < parts.size(); ++i) {
    if (!by_level.count(parts[i].level)) levels.push_back(parts[i].level);
    by_level[parts[i].level].push_back(i);
  }
  check_part_counts(building, bobj, levels, by_level);
  const std::optional<double> cell = number_attribute(bobj, "morphcut_cell_volume");
  if (!cell) building.note = "no morphcut_cell_volume attribute: levels compared with each other only";
  std::optional<double> first_sum;
  double first_area = 0, first_level = 0;
  for (double t : levels) {
    const auto& idx = by_level[t];
    check_overlaps(building, parts, idx, t, scale, opt, counts);
    // Volumes: only when every part of the level is a valid closed solid (else already reported).
    double sum = 0, area = 0;
    bool all_closed = true;
    for (size_t i : idx) {
      all_closed = all_closed && parts[i].check.closed_manifold;
      sum += parts[i].check.volume;
      area += parts[i].check.area;
    }
    if (!all_closed) continue;
    if (cell) {
      const double tol = opt.volume_rel * *cell + quantisation_bound(area, scale);
      if (*cell > 0)
        counts.max_volume_deviation = std::max(counts.max_volume_deviation, std::abs(sum - *cell) / *cell);
      if (std::abs(sum - *cell) > tol)
        add(building, vc::kPartsVolumeMismatch,
            "level " + num(t) + ": the parts add up to " + num(sum) + " m³, the cell has " + num(*cell) +
                " m³ (tolerance " + num(tol) + " m³)");
    }
    if (!first_sum) {
      first_sum = sum, first_area = area, first_level = t;
    } else {
      const double tol =
          opt.volume_rel * std::max(sum, *first_sum) + quantisation_bound(area + first_area, scale);
      if (std::abs(sum - *first_sum) > tol)
        add(building, vc::kLevelsVolumeMismatch,
            "level " + num(t) + " has " + num(sum) + " m³, level " + num(first_level) + " " +
                num(*first_sum) + " m³ (tolerance " + num(tol) + " m³)");
    }
  }
}

}  // namespace

namespace {

// Step 1: every object's structure findings, and the reader's problems on their objects (a
// problem starts with its object's id).
std::map<std::string, ObjectReport> structure_reports(const mc::io::Feature& f) {
  const json& objects = f.objects;
  std::map<std::string, ObjectReport> reports;
  for (auto it = objects.begin(); it != objects.end(); ++it) {
    ObjectReport& r = reports[it.key()];
    r.id = it.key();
    r.type = it->is_object() ? it->value("type", "") : "";
    check_structure(it.key(), *it, objects, r);
  }
  for (const auto& p : f.problems) {
    std::string owner = f.id;
    for (const auto& [id, r] : reports)
      if (p.size() > id.size() && p.compare(0, id.size() + 1, id + ":") == 0) owner = id;
    if (reports.count(owner)) add(reports[owner], vc::kReadProblem, p);
  }
  return reports;
}

// Step 2: the building's parts (children with morphcut_level, in "children" order; then any
// orphans), each checked as a solid in metres with val3dity's tolerances.
std::vector<Part> checked_parts(const mc::io::Feature& f, const json& bobj, const std::vector<Vec3>& vertices,
                                const SolidTolerances& stol, std::map<std::string, ObjectReport>& reports) {
  const json& objects = f.objects;
  std::vector<std::string> ids;
  for (const auto& c : string_list(bobj, "children"))
    if (objects.contains(c) && is_our_part(objects[c])) ids.push_back(c);
  for (auto it = objects.begin(); it != objects.end(); ++it)
    if (is_our_part(*it) && std::find(ids.begin(), ids.end(), it.key()) == ids.end()) {
      add(reports[it.key()], vc::kParentsChildren,
          "a morphcut part that the building does not list as a child");
      ids.push_back(it.key());
    }
  std::vector<Part> parts;
  for (const auto& id : ids) {
    Part p;
    p.id = id;
    p.report = std::move(reports[id]);
    const json& obj = objects[id];
    p.level = obj["attributes"]["morphcut_level"].get<double>();
    p.report.level = p.level;
    const PolygonMesh m = part_solid(obj, vertices, p.report);
    if (!m.faces.empty()) {
      p.check = check_solid(m, stol);
      for (const auto& e : p.check.errors) p.report.errors.push_back({e.code, e.name, e.message});
      if (p.check.closed_manifold) {
        p.report.volume = p.check.volume;
        p.report.convexity = p.check.convexity;
      }
    } else {
      add(p.report, vc::kInvalidObject, "the Solid has no surfaces");
    }
    parts.push_back(std::move(p));
  }
  return parts;
}

// Step 3: val3dity's 601 compares every Solid of the Building and its BuildingParts at one LoD:
// parts of several levels under one building, or an input Solid left at the LoD of the parts,
// overlap them.
void check_lod_overlaps(const mc::io::Feature& f, const std::vector<Part>& parts, ObjectReport& br) {
  const json& objects = f.objects;
  std::set<std::string> part_lods;
  std::set<double> part_levels;
  for (const Part& p : parts) {
    for (const auto& g : objects[p.id].value("geometry", json::array()))
      if (g.is_object() && g.contains("lod")) part_lods.insert(mc::io::lod_string(g["lod"]));
    part_levels.insert(p.level);
  }
  if (part_levels.size() > 1)
    add(br, vc::kPartsOverlap,
        "parts of " + std::to_string(part_levels.size()) +
            " levels hang under one Building at the same LoD and overlap each other");
  std::vector<std::string> family{f.id};
  for (size_t k = 0; k < family.size() && !part_lods.empty(); ++k) {
    const json& o = objects[family[k]];
    for (const auto& g : o.value("geometry", json::array())) {
      if (!g.is_object()) continue;
      const std::string type = g.value("type", ""),
                        lod = g.contains("lod") ? mc::io::lod_string(g["lod"]) : "";
      if ((type == "Solid" || type == "CompositeSolid") && part_lods.count(lod))
        add(br, vc::kPartsOverlap,
            "the input " + type + " of " + family[k] + " at LoD " + lod +
                " overlaps the morphcut parts at that LoD");
    }
    for (const auto& c : string_list(o, "children"))
      if (objects.contains(c) && !is_our_part(objects[c]) &&
          std::find(family.begin(), family.end(), c) == family.end())
        family.push_back(c);
  }
}

// Step 4: the building's status against its parts; ok and partial buildings' parts must tile it.
void check_status(const json& bobj, std::vector<Part>& parts, double scale, const ValidateOptions& opt,
                  ValidationCounts& counts, ObjectReport& br) {
  const bool has_attributes = bobj.contains("attributes") && bobj["attributes"].is_object();
  const std::string status = has_attributes ? bobj["attributes"].value("morphcut_status", "") : "";
  const bool level_view = has_attributes && bobj["attributes"].contains("morphcut_level");
  if ((status == "ok" || status == "partial") && parts.empty() && !level_view) {
    br.note = "annotated input: the parts are in the level outputs";
  } else if (status == "ok" || status == "partial") {
    if (parts.empty()) add(br, vc::kPartsStatusMismatch, "status " + status + " but no morphcut parts");
    else check_tiling(br, bobj, parts, scale, opt, counts);
  } else if (!parts.empty()) {
    add(br, vc::kPartsStatusMismatch,
        "status \"" + status + "\" but " + std::to_string(parts.size()) + " morphcut parts");
  } else {
    br.note =
        status.empty() ? "no parts (not processed by morphcut-city)" : "no parts (status " + status + ")";
  }
}

}  // namespace

std::vector<ObjectReport> validate_feature(const mc::io::Feature& f, const mc::io::Header& h,
                                           const ValidateOptions& opt, ValidationCounts& counts) {
  ++counts.features;
  std::map<std::string, ObjectReport> reports = structure_reports(f);
  counts.objects += reports.size();
  const mc::io::Transform t = mc::io::parse_transform(h.root, "header");
  // Checks in metres, as the parts were checked when written (core/working_frame.hpp).
  const WorkingFrame frame(h.coords, f.vertices);
  std::vector<Vec3> metric_copy;
  if (!frame.identity()) {
    metric_copy = f.vertices;
    frame.to_metric(metric_copy);
  }
  const std::vector<Vec3>& vertices = frame.identity() ? f.vertices : metric_copy;
  const double scale = grid_step_metres(t, frame, f.vertices.empty() ? Vec3{} : f.vertices.front());
  // val3dity's merge test on the coordinates as read (in metres for a non-metric CRS, where
  // val3dity's tolerances in the file's units would mean something else).
  const SolidTolerances stol{opt.snap, opt.planarity, opt.normals_deg, true, 0};
  std::vector<ObjectReport> out;
  std::set<std::string> emitted;
  if (mc::io::is_building(f) && reports.count(f.id)) {
    ++counts.buildings;
    ObjectReport br = std::move(reports[f.id]);
    const json& bobj = f.objects[f.id];
    std::vector<Part> parts = checked_parts(f, bobj, vertices, stol, reports);
    check_lod_overlaps(f, parts, br);
    check_status(bobj, parts, scale, opt, counts, br);
    (parts.empty() ? counts.buildings_without_parts : counts.buildings_with_parts)++;
    counts.invalid_buildings += !br.valid();
    emitted.insert(f.id);
    out.push_back(std::move(br));
    for (auto& p : parts) {
      ++counts.parts;
      (p.report.valid() ? counts.valid_parts : counts.invalid_parts)++;
      emitted.insert(p.id);
      out.push_back(std::move(p.report));
    }
  }
  for (auto& [id, r] : reports)
    if (!emitted.count(id) && !r.valid()) {
      ++counts.other_invalid_objects;
      out.push_back(std::move(r));
    }
  return out;
}

ValidationSummary validate_city(const std::string& path, const ValidateOptions& opt,
                                const std::function<void(const ObjectReport&)>& sink) {
  ValidationSummary s;
  s.file = path;
  mc::io::CityJsonReader reader(path);
  mc::io::Feature f;
  while (reader.next(f))
    for (const auto& r : validate_feature(f, reader.header(), opt, s.counts))
      if (sink) sink(r);
  s.file_problems = reader.problems();
  return s;
}

}  // namespace mc::output
