#include "report/html_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <memory>
#include <set>
#include <sstream>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "core/geometry.hpp"
#include "core/polygon_mesh.hpp"
#include "io/atomic_file.hpp"
#include "io/cityjson_building.hpp"
#include "io/errors.hpp"
#include "io/feature_source.hpp"
#include "report/html_assets.hpp"
#include "output/level_views.hpp"
#include "io/sha256.hpp"
#include "config/config.hpp"

namespace mc::report {

using namespace mc::output;

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;
using json = nlohmann::json;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kMm = 1000.0;  // 3D vertices: millimetre grid
constexpr double kDm = 10.0;    // plan footprints: decimetre grid

template <class J>
const J& member(const J& j, const char* key) {
  static const J null_value;
  if (!j.is_object()) return null_value;
  auto it = j.find(key);
  return it == j.end() ? null_value : *it;
}

double number_or(const ojson& j, double fallback) { return j.is_number() ? j.get<double>() : fallback; }
std::string string_or(const ojson& j, const std::string& fallback = "") {
  return j.is_string() ? j.get<std::string>() : fallback;
}

// Numbers on the page: rounded to `step` (a power of ten: 1e-3 prints as 0.402, not
// 0.40240000000000004), null for NaN.
ojson rounded(double v, double step) {
  if (!std::isfinite(v)) return nullptr;
  if (step >= 1) return std::round(v / step) * step;
  const double inv = std::round(1.0 / step);
  return std::round(v * inv) / inv;
}

ojson read_json_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw mc::io::ReadError(path + ": cannot open");
  std::stringstream ss;
  ss << in.rdbuf();
  try {
    return ojson::parse(ss.str());
  } catch (const std::exception& e) { throw mc::io::ReadError(path + ": not valid JSON (" + e.what() + ")"); }
}

// A path as written in a report: as it is when it exists, else beside the report.
std::string resolve_beside(const std::string& path, const std::string& report_path) {
  if (path.empty() || fs::exists(path) || fs::path(path).is_absolute()) return path;
  const fs::path beside = fs::path(report_path).parent_path() / fs::path(path).filename();
  return fs::exists(beside) ? beside.string() : path;
}

bool is_merged(const ojson& report) {
  return string_or(member(report, "tool")) == "morphcut-city merge-reports";
}

// The city files of one run report (not merged).
void run_report_city_files(const ojson& report, const std::string& report_path,
                           std::vector<std::string>& out) {
  const ojson& outputs = member(report, "outputs");
  auto add = [&](const ojson& p) {
    if (!p.is_string() || p.get<std::string>().empty()) return;
    const std::string r = resolve_beside(p.get<std::string>(), report_path);
    if (std::find(out.begin(), out.end(), r) == out.end()) out.push_back(r);
  };
  add(member(outputs, "cityjson"));
  const ojson& levels = member(outputs, "levels");
  if (levels.is_array())
    for (const auto& l : levels) add(member(l, "cityjson"));
}

// The settings that shape results (as merge-reports hashes them: worker threads and friends aside).
std::string config_sha256(const ojson& config) {
  if (!config.is_object()) return {};
  return mc::io::sha256_hex(mc::outputs_config_json(config).dump());
}

std::string html_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '&':
        o += "&amp;";
        break;
      case '"':
        o += "&quot;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

// ---- geometry ----

using Ring = std::vector<uint32_t>;

// One embedded building: its vertices on the millimetre grid (absolute until written), the input
// ghost and each level's parts.
struct Geometry {
  std::map<std::array<int64_t, 3>, uint32_t> index;
  std::vector<std::array<int64_t, 3>> v;
  ojson ghost = ojson::array();
  std::map<double, ojson, std::greater<>> levels;  // threshold -> parts

  uint32_t add(const Vec3& p) {
    const std::array<int64_t, 3> q{std::llround(p.x * kMm), std::llround(p.y * kMm), std::llround(p.z * kMm)};
    auto [it, fresh] = index.try_emplace(q, static_cast<uint32_t>(v.size()));
    if (fresh) v.push_back(q);
    return it->second;
  }
  // A face: its outer ring alone when it has no hole, else [outer, hole, ...]. Consecutive
  // duplicates (collapsed on the grid) are dropped; faces left with < 3 vertices are skipped.
  void add_face(ojson& out, const std::vector<std::vector<Vec3>>& rings) {
    ojson rs = ojson::array();
    for (const auto& ring : rings) {
      Ring r;
      for (const Vec3& p : ring) {
        const uint32_t i = add(p);
        if (r.empty() || r.back() != i) r.push_back(i);
      }
      while (r.size() > 1 && r.front() == r.back()) r.pop_back();
      if (r.size() >= 3) rs.push_back(r);
      else if (rs.empty()) return;  // the outer ring collapsed
    }
    if (rs.empty()) return;
    out.push_back(rs.size() == 1 ? rs[0] : rs);
  }
};

struct Building {
  std::string id, status, reason, tile, role;
  double job = kNaN, faces = kNaN, hausdorff = kNaN;
  std::map<double, int, std::greater<>> parts;  // threshold -> parts
  std::map<double, double, std::greater<>> convexity;
  bool from_report = false;
  bool ghost_done = false;
  bool want_3d = false;
  size_t rank = 0;  // priority for 3D geometry (rank_3d; file order without a report)
  // Footprint rings (absolute coordinates) and centroid for the plan view.
  std::vector<std::vector<std::array<double, 2>>> footprint;
  double cx = kNaN, cy = kNaN;
  // Which file gave each level's parts (a level is taken from the first file that has it).
  std::map<double, size_t> level_file;
  // Parts' volume-weighted convexity sums, for a page made without a report.
  std::map<double, std::array<double, 2>, std::greater<>> part_sums;  // volume, volume * convexity
  double role_volume = -1, role_level = kNaN;
  std::unique_ptr<Geometry> geo;
};

Vec3 newell_normal(const std::vector<Vec3>& vs, const Polygon& f) {
  return f.rings.empty() ? Vec3{0, 0, 0} : normalized(ring_area_vector(vs, f.rings[0]));
}

// The plan view's outline of a building: its GroundSurface faces, else its downward faces, else
// its upward ones (roofs), projected vertically; outer rings only.
void set_footprint(Building& b, const PolygonMesh& m) {
  int32_t ground = -1;
  for (size_t i = 0; i < m.semantic_labels.size(); ++i)
    if (m.semantic_labels[i] == "GroundSurface") ground = static_cast<int32_t>(i);
  std::vector<const Polygon*> picked;
  for (const Polygon& f : m.faces)
    if (ground >= 0 && f.semantic == ground) picked.push_back(&f);
  for (double sign : {-1.0, 1.0}) {
    if (!picked.empty()) break;
    for (const Polygon& f : m.faces)
      if (sign * newell_normal(m.vertices, f).z > 0.5) picked.push_back(&f);
  }
  double sx = 0, sy = 0;
  size_t n = 0;
  for (const Polygon* f : picked) {
    if (f->rings.empty() || f->rings[0].size() < 3) continue;
    std::vector<std::array<double, 2>> ring;
    for (uint32_t i : f->rings[0]) {
      if (i >= m.vertices.size()) continue;
      ring.push_back({m.vertices[i].x, m.vertices[i].y});
      sx += m.vertices[i].x;
      sy += m.vertices[i].y;
      ++n;
    }
    if (ring.size() >= 3) b.footprint.push_back(std::move(ring));
  }
  if (n == 0)
    for (const Vec3& p : m.vertices) sx += p.x, sy += p.y, ++n;
  if (n) b.cx = sx / static_cast<double>(n), b.cy = sy / static_cast<double>(n);
}

// The faces of a part's geometry (Solid shells, or surfaces), as coordinate rings.
std::vector<std::vector<std::vector<Vec3>>> part_faces(const json& obj, const std::vector<Vec3>& vs) {
  std::vector<std::vector<std::vector<Vec3>>> faces;
  const json& geoms = member(obj, "geometry");
  if (!geoms.is_array()) return faces;
  for (const json& g : geoms) {
    const std::string type = member(g, "type").is_string() ? member(g, "type").get<std::string>() : "";
    const json& b = member(g, "boundaries");
    if (!b.is_array()) continue;
    auto add_surface = [&](const json& surface) {
      if (!surface.is_array()) return;
      std::vector<std::vector<Vec3>> rings;
      for (const json& ring : surface) {
        if (!ring.is_array()) continue;
        std::vector<Vec3> r;
        for (const json& i : ring)
          if (i.is_number_integer() && i.get<int64_t>() >= 0 && i.get<uint64_t>() < vs.size())
            r.push_back(vs[i.get<size_t>()]);
        rings.push_back(std::move(r));
      }
      faces.push_back(std::move(rings));
    };
    if (type == "Solid") {
      for (const json& shell : b)
        if (shell.is_array())
          for (const json& s : shell) add_surface(s);
    } else if (type == "MultiSurface" || type == "CompositeSurface") {
      for (const json& s : b) add_surface(s);
    } else {
      continue;
    }
    break;  // a part has one geometry; take the first usable one
  }
  return faces;
}

// ---- the page's data ----

struct Page {
  ojson meta = ojson::object();
  std::vector<double> levels;  // descending (coarse to fine)
  std::vector<Building> buildings;
  std::unordered_map<std::string, size_t> by_id;
  std::vector<std::string> tiles;
  std::vector<std::string> warnings;
  // Degrees (or feet) are drawn in metres: one metric frame for the whole page, set by the first
  // building read (core/working_frame.hpp; over a city the scale error stays below 1e-6).
  std::optional<WorkingFrame> frame;

  Building& add(const std::string& id) {
    by_id.emplace(id, buildings.size());
    buildings.emplace_back();
    buildings.back().id = id;
    return buildings.back();
  }
};

void read_report(const std::string& path, Page& page) {
  const ojson report = read_json_file(path);
  if (!report.is_object() || !member(report, "buildings").is_array())
    throw mc::io::ReadError(path + ": not a morphcut-city run report (no buildings)");
  const bool merged = is_merged(report);
  ojson& meta = page.meta;
  meta["kind"] = merged ? "merged" : "run";
  meta["report"] = path;
  meta["tool"] = member(report, "tool");
  meta["version"] = member(report, "version");
  double job_sum = 0;
  if (merged) {
    const ojson& totals = member(report, "totals");
    meta["wall_seconds"] = member(totals, "wall_seconds");
    meta["building_count"] = member(totals, "building_count");
    meta["counts"] = member(totals, "counts");
    meta["cache"] = member(totals, "cache");
    ojson tiles = ojson::array();
    std::set<std::string> configs;
    for (const auto& t : member(report, "tiles")) {
      tiles.push_back({{"tile", member(t, "tile")},
                       {"input", member(t, "input")},
                       {"building_count", member(t, "building_count")},
                       {"counts", member(t, "counts")},
                       {"wall_seconds", member(t, "wall_seconds")},
                       {"config_sha256", member(t, "config_sha256")}});
      if (member(t, "config_sha256").is_string())
        configs.insert(member(t, "config_sha256").get<std::string>());
    }
    meta["tiles"] = tiles;
    meta["missing_tiles"] = member(report, "missing_tiles");
    meta["config_sha256"] = configs.size() == 1 ? ojson(*configs.begin()) : ojson(nullptr);
    meta["merge_warnings"] = member(report, "warnings");
    meta["duplicates"] = member(totals, "duplicate_ids");
  } else {
    const ojson& input = member(report, "input");
    meta["input"] = {{"path", member(input, "path")},       {"format", member(input, "format")},
                     {"version", member(input, "version")}, {"crs", member(input, "crs")},
                     {"bytes", member(input, "bytes")},     {"sha256", member(input, "sha256")}};
    meta["config_file"] = member(report, "config_file");
    meta["config_sha256"] = config_sha256(member(report, "config"));
    meta["wall_seconds"] = member(report, "wall_seconds");
    meta["cpu_seconds"] = member(report, "cpu_seconds");
    meta["threads"] = member(report, "threads");
    meta["peak_rss_mb"] = member(report, "peak_rss_mb");
    meta["building_count"] = member(report, "building_count");
    meta["features"] = member(report, "features");
    meta["counts"] = member(report, "counts");
    meta["cache"] = member(report, "cache");
    meta["reader_problems"] = member(report, "reader_problems");
  }
  std::set<double> levels;
  for (const auto& e : report["buildings"]) {
    const std::string id = string_or(member(e, "id"));
    if (id.empty()) continue;
    Building& b = page.add(id);  // duplicates (tile borders) keep their own rows
    b.from_report = true;
    b.status = string_or(member(e, "status"), "?");
    b.reason = string_or(member(e, "reason"));
    b.tile = string_or(member(e, "tile"));
    b.job = number_or(member(member(e, "timings"), "job"), kNaN);
    if (std::isfinite(b.job)) job_sum += b.job;
    b.faces = number_or(member(member(e, "sizes"), "input_faces"), kNaN);
    b.hausdorff = number_or(member(e, "hausdorff"), kNaN);
    for (const auto& l : member(e, "levels")) {
      const double t = number_or(member(l, "threshold"), kNaN);
      if (!std::isfinite(t)) continue;
      levels.insert(t);
      b.parts[t] = static_cast<int>(number_or(member(l, "parts"), 0));
      b.convexity[t] = number_or(member(l, "convexity"), kNaN);
    }
  }
  meta["job_seconds_sum"] = rounded(job_sum, 1e-3);
  page.levels.assign(levels.rbegin(), levels.rend());
}

// The order in which buildings get 3D geometry (see the header): failed, partial, then the
// slowest and the least convex at the finest level alternately. The first `bound` are read with
// geometry; page_data may drop the last of them to keep within the byte budget.
void rank_3d(Page& page, size_t bound) {
  auto& bs = page.buildings;
  std::vector<size_t> ranked;
  std::vector<bool> taken(bs.size(), false);
  auto take = [&](size_t i) {
    if (!taken[i]) taken[i] = true, ranked.push_back(i);
  };
  for (const char* s : {"failed", "partial"})
    for (size_t i = 0; i < bs.size(); ++i)
      if (bs[i].status == s) take(i);
  std::vector<size_t> slow(bs.size()), convex;
  for (size_t i = 0; i < slow.size(); ++i) slow[i] = i;
  convex = slow;
  auto job = [&](size_t i) { return std::isfinite(bs[i].job) ? bs[i].job : -1.0; };
  std::stable_sort(slow.begin(), slow.end(), [&](size_t a, size_t b) { return job(a) > job(b); });
  auto finest_cvx = [&](size_t i) {  // the map is coarse to fine: its last entry is the finest level
    const auto& c = bs[i].convexity;
    return c.empty() || !std::isfinite(c.rbegin()->second) ? 2.0 : c.rbegin()->second;
  };
  std::stable_sort(convex.begin(), convex.end(),
                   [&](size_t a, size_t b) { return finest_cvx(a) < finest_cvx(b); });
  for (size_t k = 0; k < bs.size(); ++k) take(slow[k]), take(convex[k]);
  for (size_t r = 0; r < ranked.size(); ++r) {
    bs[ranked[r]].rank = r;
    bs[ranked[r]].want_3d = r < bound;
  }
}

// The page's building for a feature, added (ranked, with or without 3D) when new.
Building& building_for(Page& page, const std::string& id, const HtmlReportOptions& opt, bool have_report) {
  auto found = page.by_id.find(id);
  if (found != page.by_id.end()) return page.buildings[found->second];
  Building& nb = page.add(id);
  nb.rank = page.buildings.size() - 1;
  nb.want_3d = !have_report && nb.rank < opt.max_3d_buildings;
  return nb;
}

// Without a report: status, reason, Hausdorff distance and part counts from the Building's
// morphcut attributes.
void status_from_attributes(const json& battr, Building& b, std::set<double>& new_levels) {
  if (b.from_report || !b.status.empty() || !member(battr, "morphcut_status").is_string()) return;
  b.status = member(battr, "morphcut_status").get<std::string>();
  if (member(battr, "morphcut_reason").is_string())
    b.reason = member(battr, "morphcut_reason").get<std::string>();
  if (member(battr, "morphcut_hausdorff").is_number())
    b.hausdorff = member(battr, "morphcut_hausdorff").get<double>();
  const json& ps = member(battr, "morphcut_parts");
  const json& ls = member(battr, "morphcut_levels");
  if (ps.is_array() && ls.is_array())
    for (size_t i = 0; i < std::min(ps.size(), ls.size()); ++i)
      if (ps[i].is_number() && ls[i].is_number()) {
        b.parts[ls[i].get<double>()] = ps[i].get<int>();
        new_levels.insert(ls[i].get<double>());
      }
}

// Parts: BuildingParts with morphcut_level, each level from the first file that has it (a
// per-level file also marks the Building itself with the level it shows).
void read_parts(const mc::io::Feature& f, size_t file_index, Building& b, std::set<double>& new_levels) {
  for (auto it = f.objects.begin(); it != f.objects.end(); ++it) {
    if (!member(it.value(), "type").is_string() ||
        member(it.value(), "type").get<std::string>() != "BuildingPart")
      continue;
    const json& attr = member(it.value(), "attributes");
    const json& level = member(attr, "morphcut_level");
    if (!level.is_number()) continue;
    const double t = level.get<double>();
    const auto [lf, fresh] = b.level_file.try_emplace(t, file_index);
    if (!fresh && lf->second != file_index) continue;
    new_levels.insert(t);
    const double volume = member(attr, "volume").is_number() ? member(attr, "volume").get<double>() : 0.0;
    const double cvx = member(attr, "convexity").is_number() ? member(attr, "convexity").get<double>() : kNaN;
    const json& role = member(attr, "morphcut_role");
    // The building's role: that of its largest part at the coarsest level.
    if (role.is_string() &&
        (!std::isfinite(b.role_level) || t > b.role_level || (t == b.role_level && volume > b.role_volume))) {
      b.role = role.get<std::string>();
      b.role_level = t;
      b.role_volume = volume;
    }
    auto& s = b.part_sums.try_emplace(t, std::array<double, 2>{0, 0}).first->second;
    if (std::isfinite(cvx)) s[0] += volume, s[1] += volume * cvx;
    if (!b.want_3d) continue;
    if (!b.geo) b.geo = std::make_unique<Geometry>();
    ojson faces = ojson::array();
    for (const auto& rings : part_faces(it.value(), f.vertices)) b.geo->add_face(faces, rings);
    const json& nb = member(attr, "neighbours");
    ojson& lvl = b.geo->levels.try_emplace(t, ojson::array()).first->second;
    lvl.push_back(ojson::array(
        {member(attr, "morphcut_index").is_number() ? ojson(member(attr, "morphcut_index"))
                                                    : ojson(lvl.size()),
         rounded(volume, 1e-3), rounded(cvx, 1e-4), nb.is_array() ? nb.size() : 0,
         role.is_string() ? ojson(role.get<std::string>()) : ojson(nullptr), it.key(), std::move(faces)}));
  }
}

// The input ghost and footprint: the building's own geometry without morphcut parts.
void read_ghost(mc::io::Feature& f, const mc::io::Header& header, Building& b) {
  if (b.ghost_done) return;
  strip_previous_parts(f);
  const mc::io::BuildingInput in = mc::io::extract_building(f, header, "highest");
  if (in.mesh.empty()) return;
  b.ghost_done = true;
  set_footprint(b, in.mesh);
  if (!b.want_3d) return;
  if (!b.geo) b.geo = std::make_unique<Geometry>();
  for (const Polygon& face : in.mesh.faces) {
    std::vector<std::vector<Vec3>> rings;
    for (const auto& r : face.rings) {
      std::vector<Vec3> ring;
      for (uint32_t i : r)
        if (i < in.mesh.vertices.size()) ring.push_back(in.mesh.vertices[i]);
      rings.push_back(std::move(ring));
    }
    b.geo->add_face(b.geo->ghost, rings);
  }
}

void read_city_file(const std::string& path, size_t file_index, Page& page, const HtmlReportOptions& opt,
                    bool have_report) {
  std::unique_ptr<mc::io::FeatureSource> src;
  try {
    src = mc::io::open_feature_source(path);
  } catch (const std::exception& e) {
    page.warnings.push_back(std::string("city file not read: ") + e.what());
    return;
  }
  const mc::io::Header header = src->header();
  mc::io::Feature f;
  std::set<double> new_levels;
  while (true) {
    try {
      if (!src->next(f)) break;
    } catch (const std::exception& e) {
      page.warnings.push_back(path + ": reading stopped: " + e.what());
      break;
    }
    if (!mc::io::is_building(f)) continue;
    if (!header.coords.metric()) {
      if (!page.frame) page.frame.emplace(header.coords, f.vertices);
      page.frame->to_metric(f.vertices);
    }
    Building& b = building_for(page, f.id, opt, have_report);
    status_from_attributes(member(member(f.objects, f.id.c_str()), "attributes"), b, new_levels);
    read_parts(f, file_index, b, new_levels);
    read_ghost(f, header, b);
  }
  // Levels found only in the city files (no report, or other output levels).
  std::set<double> all(page.levels.begin(), page.levels.end());
  all.insert(new_levels.begin(), new_levels.end());
  page.levels.assign(all.rbegin(), all.rend());
}

ojson level_array(const std::map<double, double, std::greater<>>& m, const std::vector<double>& levels,
                  double step) {
  ojson a = ojson::array();
  for (double t : levels) {
    auto it = m.find(t);
    a.push_back(it == m.end() ? ojson(nullptr) : rounded(it->second, step));
  }
  return a;
}

// Step 1: without a report, counts and convexities come from the parts themselves.
void fill_from_parts(Page& page) {
  for (Building& b : page.buildings) {
    if (b.from_report) continue;
    for (const auto& [t, s] : b.part_sums) {
      if (!b.convexity.count(t) && s[0] > 0) b.convexity[t] = s[1] / s[0];
      if (!b.parts.count(t) && b.level_file.count(t)) {
        int n = 0;  // parts counted from the geometry read
        if (b.geo && b.geo->levels.count(t)) n = static_cast<int>(b.geo->levels[t].size());
        if (n) b.parts[t] = n;
      }
    }
    if (b.status.empty()) b.status = "?";
  }
}

// Step 2: the local origin: the city's minimum x/y, in whole metres.
std::array<double, 2> local_origin(const Page& page) {
  double ox = std::numeric_limits<double>::infinity(), oy = ox;
  for (const Building& b : page.buildings) {
    for (const auto& r : b.footprint)
      for (const auto& p : r) ox = std::min(ox, p[0]), oy = std::min(oy, p[1]);
    if (std::isfinite(b.cx)) ox = std::min(ox, b.cx), oy = std::min(oy, b.cy);
    if (b.geo)
      for (const auto& v : b.geo->v) ox = std::min(ox, v[0] / kMm), oy = std::min(oy, v[1] / kMm);
  }
  if (!std::isfinite(ox)) ox = oy = 0;
  return {std::floor(ox), std::floor(oy)};
}

// Step 3: each embedded building's geometry; then, by rank, as many as fit in the byte budget
// (the others null). Counts those left out in `over_budget`.
std::vector<ojson> embedded_geometry(Page& page, const HtmlReportOptions& opt, double ox, double oy,
                                     size_t& over_budget) {
  std::vector<ojson> geo_json(page.buildings.size());
  std::vector<size_t> with_geo;
  for (size_t i = 0; i < page.buildings.size(); ++i) {
    Building& b = page.buildings[i];
    if (!b.geo || b.geo->v.empty()) continue;
    Geometry& g = *b.geo;
    std::array<int64_t, 3> lo = g.v[0];
    for (const auto& v : g.v)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]);
    ojson verts = ojson::array();
    for (const auto& v : g.v)
      for (int k = 0; k < 3; ++k) verts.push_back(v[k] - lo[k]);
    ojson levels = ojson::array();
    for (double t : page.levels) {
      auto it = g.levels.find(t);
      levels.push_back(it == g.levels.end() ? ojson(nullptr) : std::move(it->second));
    }
    const ojson origin = {rounded(lo[0] / kMm - ox, 1e-3), rounded(lo[1] / kMm - oy, 1e-3),
                          rounded(lo[2] / kMm, 1e-3)};
    geo_json[i] = {
        {"o", origin}, {"v", std::move(verts)}, {"ghost", std::move(g.ghost)}, {"l", std::move(levels)}};
    b.geo.reset();
    with_geo.push_back(i);
  }
  std::stable_sort(with_geo.begin(), with_geo.end(),
                   [&](size_t a, size_t b) { return page.buildings[a].rank < page.buildings[b].rank; });
  size_t geo_bytes = 0;
  for (size_t i : with_geo) {
    const size_t n = geo_json[i].dump().size();
    if (geo_bytes + n > opt.max_3d_bytes) geo_json[i] = nullptr, ++over_budget;
    else geo_bytes += n;
  }

  return geo_json;
}

// A footprint's rings on the decimetre grid about the origin, repeats dropped, flat x, y lists.
ojson footprint_json(const Building& b, double ox, double oy) {
  ojson fp = ojson::array();
  for (const auto& ring : b.footprint) {
    std::vector<std::array<int64_t, 2>> q;  // on the decimetre grid, repeats dropped
    for (const auto& p : ring) {
      const std::array<int64_t, 2> g{std::llround((p[0] - ox) * kDm), std::llround((p[1] - oy) * kDm)};
      if (q.empty() || q.back() != g) q.push_back(g);
    }
    while (q.size() > 1 && q.front() == q.back()) q.pop_back();
    if (q.size() < 3) continue;
    ojson flat = ojson::array();
    for (const auto& g : q) flat.push_back(g[0]), flat.push_back(g[1]);
    fp.push_back(std::move(flat));
  }
  return fp;
}

ojson page_data(Page& page, const HtmlReportOptions& opt) {
  fill_from_parts(page);
  const std::array<double, 2> origin = local_origin(page);
  const double ox = origin[0], oy = origin[1];
  size_t with_fp = 0;
  for (const Building& b : page.buildings) with_fp += !b.footprint.empty();
  const bool draw_footprints = with_fp <= opt.max_footprints;
  size_t over_budget = 0;
  std::vector<ojson> geo_json = embedded_geometry(page, opt, ox, oy, over_budget);
  ojson rows = ojson::array();
  ojson geometry = ojson::array();
  std::map<std::string, size_t> tile_index;
  size_t with_3d = 0, footprints = 0;
  bool roles = false;
  size_t i = 0;
  for (Building& b : page.buildings) {
    ojson r = {{"id", b.id}, {"s", b.status}};
    if (!b.reason.empty()) r["r"] = b.reason;
    if (!b.tile.empty()) r["t"] = tile_index.try_emplace(b.tile, tile_index.size()).first->second;
    if (std::isfinite(b.job)) r["j"] = rounded(b.job, 1e-4);
    if (std::isfinite(b.faces)) r["f"] = static_cast<int64_t>(b.faces);
    if (std::isfinite(b.hausdorff)) r["h"] = rounded(b.hausdorff, 1e-4);
    ojson parts = ojson::array();
    for (double t : page.levels) {
      auto it = b.parts.find(t);
      parts.push_back(it == b.parts.end() ? ojson(nullptr) : ojson(it->second));
    }
    r["p"] = parts;
    r["c"] = level_array(b.convexity, page.levels, 1e-4);
    if (!b.role.empty()) r["ro"] = b.role, roles = true;
    if (std::isfinite(b.cx)) r["xy"] = {rounded(b.cx - ox, 0.1), rounded(b.cy - oy, 0.1)};
    if (draw_footprints && !b.footprint.empty()) {
      ojson fp = footprint_json(b, ox, oy);
      if (!fp.empty()) r["fp"] = std::move(fp), ++footprints;
    }
    if (!geo_json[i].is_null()) {
      r["g"] = with_3d++;  // index into geometry
      geometry.push_back(std::move(geo_json[i]));
    }
    rows.push_back(std::move(r));
    ++i;
  }
  ojson tiles = ojson::array();
  std::vector<std::string> names(tile_index.size());
  for (const auto& [name, i] : tile_index) names[i] = name;
  for (auto& n : names) tiles.push_back(n);

  ojson& meta = page.meta;
  meta["levels"] = page.levels;
  meta["origin"] = {ox, oy};
  meta["crs"] = member(member(meta, "input"), "crs");
  meta["bound"] = {
      {"max_3d", opt.max_3d_buildings},
      {"max_3d_mb", static_cast<double>(opt.max_3d_bytes) / 1e6},
      {"with_3d", with_3d},
      {"over_budget", over_budget},
      {"max_footprints", opt.max_footprints},
      {"footprints", footprints},
      {"footprints_capped", !draw_footprints},
      {"rule", page.buildings.size() <= opt.max_3d_buildings && over_budget == 0
                   ? "every building"
                   : "failed and partial buildings first, then the slowest and the least convex at "
                     "the finest level alternately"}};
  meta["roles"] = roles;
  meta["three"] = html_assets::kHasThree;
  meta["warnings"] = page.warnings;
  return ojson{{"format", 1},
               {"meta", meta},
               {"tiles", tiles},
               {"buildings", std::move(rows)},
               {"geometry", std::move(geometry)}};
}

}  // namespace

std::string html_path_for_report(const std::string& report_path) {
  if (report_path.ends_with(".report.json")) return report_path.substr(0, report_path.size() - 12) + ".html";
  return report_path + ".html";
}

std::vector<std::string> city_files_of_report(const std::string& report_json_path) {
  std::vector<std::string> out;
  ojson report;
  try {
    report = read_json_file(report_json_path);
  } catch (const std::exception&) { return out; }
  if (!is_merged(report)) {
    run_report_city_files(report, report_json_path, out);
    return out;
  }
  for (const auto& t : member(report, "tiles")) {
    const std::string tile_report = resolve_beside(string_or(member(t, "report")), report_json_path);
    try {
      run_report_city_files(read_json_file(tile_report), tile_report, out);
    } catch (const std::exception&) {}
  }
  return out;
}

HtmlReportResult write_html_report(const std::string& report_json_path,
                                   const std::vector<std::string>& city_paths,
                                   const std::string& out_html_path, const HtmlReportOptions& opt) {
  Page page;
  const bool have_report = !report_json_path.empty();
  if (have_report) read_report(report_json_path, page);
  else page.meta["kind"] = "city";
  HtmlReportResult res;
  res.city_files = city_paths.empty() && have_report ? city_files_of_report(report_json_path) : city_paths;
  if (have_report) rank_3d(page, opt.max_3d_buildings);
  for (size_t i = 0; i < res.city_files.size(); ++i)
    read_city_file(res.city_files[i], i, page, opt, have_report);
  if (!have_report && page.buildings.empty())
    throw mc::io::ReadError("no buildings found in the city files given and no report");
  if (!have_report && !page.buildings.empty()) {
    ojson input = {{"path", res.city_files.empty() ? ojson(nullptr) : ojson(res.city_files[0])}};
    page.meta["input"] = input;
    ojson counts = ojson::object();
    for (const Building& b : page.buildings) counts[b.status] = number_or(counts[b.status], 0) + 1;
    page.meta["counts"] = counts;
    page.meta["building_count"] = page.buildings.size();
  }
  size_t no_geometry = 0;
  for (const Building& b : page.buildings) no_geometry += !b.ghost_done;
  if (no_geometry)
    page.warnings.push_back(std::to_string(no_geometry) +
                            " buildings have no surface geometry in the city files read");
  page.meta["city_files"] = res.city_files;

  // Title: the input's (or the report's) name.
  std::string name = string_or(member(member(page.meta, "input"), "path"));
  if (name.empty()) name = have_report ? report_json_path : "city";
  name = name == "-" ? "stdin" : fs::path(name).filename().string();
  page.meta["title"] = "morphcut-city: " + name;

  res.buildings = page.buildings.size();
  res.warnings = page.warnings;
  const ojson data = page_data(page, opt);
  res.with_3d = data["meta"]["bound"]["with_3d"].get<size_t>();
  res.footprints = data["meta"]["bound"]["footprints"].get<size_t>();

  // JSON inside <script>: '<' only occurs in strings, where \u003c is the same character.
  std::string text = data.dump(-1, ' ', false, ojson::error_handler_t::replace);
  std::string safe;
  safe.reserve(text.size() + 64);
  for (char c : text) {
    if (c == '<') safe += "\\u003c";
    else safe += c;
  }
  text.clear();

  const std::string tmpl = html_assets::kPageHtml;
  const std::string title = html_escape("morphcut-city: " + name);
  const std::map<std::string, std::string_view> parts = {{"@TITLE@", title},
                                                         {"@CSS@", html_assets::kPageCss},
                                                         {"@DATA@", safe},
                                                         {"@THREE@", html_assets::kThreeJs},
                                                         {"@JS@", html_assets::kPageJs}};
  std::unique_ptr<mc::io::AtomicFile> file;
  try {
    file = std::make_unique<mc::io::AtomicFile>(out_html_path);
  } catch (const std::exception& e) { throw mc::io::WriteError(out_html_path + ": " + e.what()); }
  std::ostream& o = file->stream();
  size_t at = 0;
  while (at < tmpl.size()) {
    const size_t p = tmpl.find('@', at);
    if (p == std::string::npos) {
      o << std::string_view(tmpl).substr(at);
      break;
    }
    o << std::string_view(tmpl).substr(at, p - at);
    bool replaced = false;
    for (const auto& [key, value] : parts)
      if (tmpl.compare(p, key.size(), key) == 0) {
        o << value;
        at = p + key.size();
        replaced = true;
        break;
      }
    if (!replaced) {
      o << '@';
      at = p + 1;
    }
  }
  try {
    file->commit();
  } catch (const std::exception& e) { throw mc::io::WriteError(out_html_path + ": " + e.what()); }
  res.path = out_html_path;
  std::error_code ec;
  res.bytes = fs::file_size(out_html_path, ec);
  return res;
}

}  // namespace mc::report
