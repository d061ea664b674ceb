#include "massing/massing.hpp"

#include <cpl_error.h>
#include <ogr_geometry.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numeric>

#include "core/decompose.hpp"
#include "core/hull.hpp"
#include "core/union_find.hpp"
#include "massing/masses.hpp"
#include "massing/plan_geometry.hpp"
#include "massing/roles.hpp"

namespace mc::massing {

using mc::io::MultiPolygon2;
using mc::io::Polygon2;
using mc::io::Ring2;
using nlohmann::json;

namespace {

constexpr double kPi = 3.14159265358979323846;

double rounded(double v, double step) { return std::isfinite(v) ? std::round(v / step) * step : v; }

// Vector area (half the sum of cross products) of a 3D ring.
Vec3 vector_area(const PolygonMesh& m, const std::vector<uint32_t>& ring) {
  Vec3 s{};
  for (size_t i = 0, n = ring.size(); i < n; ++i)
    s += cross(m.vertices[ring[i]], m.vertices[ring[(i + 1) % n]]);
  return s * 0.5;
}

// A face at the top of its part: its outer ring within `depth` below z_max (a flat roof, not a
// step or a low terrace).
bool top_face(const PolygonMesh& m, const Polygon& f, double z_max, double depth) {
  if (f.rings.empty()) return false;
  for (uint32_t v : f.rings[0])
    if (m.vertices[v].z < z_max - depth) return false;
  return true;
}

// Area and unit normal of a face with holes (the outer ring's orientation).
std::pair<double, Vec3> face_area(const PolygonMesh& m, const Polygon& f) {
  if (f.rings.empty()) return {0, {}};
  const Vec3 outer = vector_area(m, f.rings[0]);
  double a = norm(outer);
  for (size_t r = 1; r < f.rings.size(); ++r) a -= norm(vector_area(m, f.rings[r]));
  return {std::max(0.0, a), normalized(outer)};
}

// The part's vertical projection: the 2D hull for a convex part, else the union of its
// downward-facing faces projected (every vertical line through the part enters it through one).
MultiPolygon2 part_footprint(const PolygonMesh& m, bool convex) {
  std::vector<Pt> pts;
  pts.reserve(m.vertices.size());
  for (const Vec3& v : m.vertices) pts.push_back({snap(v.x), snap(v.y)});
  if (!convex) {
    std::vector<Polygon2> down;
    for (const Polygon& f : m.faces) {
      const auto [area, n] = face_area(m, f);
      if (!(area > 0) || !(n.z < -1e-6)) continue;
      Polygon2 p;
      for (const auto& ring : f.rings) {
        Ring2 r;
        for (uint32_t v : ring) r.push_back({snap(m.vertices[v].x), snap(m.vertices[v].y)});
        p.push_back(std::move(r));
      }
      if (std::abs(polygon_area(p)) > 1e-9) down.push_back(std::move(p));
    }
    bool ok = false;
    MultiPolygon2 u = union_of(down, ok);
    if (ok && !u.empty()) return u;
  }
  Ring2 h = mc::convex_hull_2d(pts);
  if (h.size() < 3) return {};
  return {{h}};
}

const char* kind_name(double nz, double stacked_cos, double side_sin) {
  if (std::abs(nz) >= stacked_cos) return "stacked";
  if (std::abs(nz) <= side_sin) return "side";
  return "inclined";
}

size_t analysis_index(const BuildingMassing& m, double level) {
  size_t best = 0;
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < m.levels.size(); ++i) {
    const double x = std::abs(std::log(m.levels[i].threshold) - std::log(level));
    if (x < d - 1e-12) d = x, best = i;
  }
  return best;
}

json rings_json(const MultiPolygon2& m) {
  json a = json::array();
  for (const auto& poly : m) {
    json p = json::array();
    for (const auto& r : poly) {
      json rr = json::array();
      for (const auto& pt : r) rr.push_back({pt[0], pt[1]});
      p.push_back(std::move(rr));
    }
    a.push_back(std::move(p));
  }
  return a;
}

MultiPolygon2 rings_from_json(const json& a) {
  MultiPolygon2 m;
  for (const auto& p : a) {
    Polygon2 poly;
    for (const auto& r : p) {
      Ring2 ring;
      for (const auto& pt : r) ring.push_back({pt[0].get<double>(), pt[1].get<double>()});
      poly.push_back(std::move(ring));
    }
    m.push_back(std::move(poly));
  }
  return m;
}

std::string part_name(const std::string& building, size_t level, size_t index) {
  return building + "-mc" + std::to_string(level) + "-" + std::to_string(index);
}

const char* position(int above) { return above > 0 ? "above" : above < 0 ? "below" : "beside"; }

}  // namespace

Contact contact_from(uint32_t other, const KindAreas& kinds) {
  Contact c;
  c.other = other;
  double best = -1;
  for (const auto& [kind, v] : kinds) {
    c.area += v.first;
    if (v.first > best) best = v.first, c.kind = kind;
  }
  if (c.kind != "side") {
    const double up = kinds.at(c.kind).second;
    c.above = up > 0 ? 1 : up < 0 ? -1 : 0;
  }
  return c;
}

LevelMassing analyse_level(const std::vector<PolygonMesh>& meshes, const std::vector<PartResult>& parts,
                           size_t index, double threshold, const MassingParams& p) {
  LevelMassing L;
  L.index = index;
  L.threshold = threshold;
  const size_t n = meshes.size();
  L.parts.resize(n);
  const double stacked_cos = std::cos(p.stacked_angle_deg * kPi / 180);
  const double side_sin = std::sin(p.side_angle_deg * kPi / 180);
  double ground = std::numeric_limits<double>::infinity();
  for (size_t j = 0; j < n; ++j) {
    const PolygonMesh& m = meshes[j];
    PartMassing& pm = L.parts[j];
    pm.z_min = std::numeric_limits<double>::infinity();
    pm.z_max = -std::numeric_limits<double>::infinity();
    for (const Vec3& v : m.vertices) pm.z_min = std::min(pm.z_min, v.z), pm.z_max = std::max(pm.z_max, v.z);
    if (m.vertices.empty()) pm.z_min = pm.z_max = 0;
    ground = std::min(ground, pm.z_min);
    pm.volume = j < parts.size() ? parts[j].volume : 0;
    pm.hull_volume = j < parts.size() ? parts[j].hull_volume : 0;
    if (!(pm.hull_volume > 0)) pm.hull_volume = convex_hull(m.vertices).volume;
    pm.convexity = pm.hull_volume > 0 ? std::min(1.0, pm.volume / pm.hull_volume) : 0.0;
    pm.footprint = part_footprint(m, pm.convexity >= 0.999);
    pm.footprint_area = multipolygon_area(pm.footprint);
    std::vector<Pt> outer;
    for (const auto& poly : pm.footprint)
      if (!poly.empty()) outer.insert(outer.end(), poly[0].begin(), poly[0].end());
    const PlanExtent extent = plan_extent(mc::convex_hull_2d(outer));
    pm.width = extent.width;
    pm.length = extent.length;
    // Contacts: shared faces by neighbour and kind.
    std::map<uint32_t, KindAreas> acc;  // other -> kind -> (area, signed area with this part above)
    double own = 0, walls = 0;          // the part's own faces' area, and its walls'
    double flat_up = 0;                 // horizontal upward faces' area in the top quarter
    double ground_down = 0;             // its own downward faces on the input's ground surface
    const double top_depth = std::max(p.mass_height_tolerance, (pm.z_max - pm.z_min) / 4);
    for (const Polygon& f : m.faces) {
      const auto [area, nrm] = face_area(m, f);
      if (nrm.z >= stacked_cos && top_face(m, f, pm.z_max, top_depth)) flat_up += area;
      if (f.neighbour < 0 || static_cast<size_t>(f.neighbour) >= n || static_cast<size_t>(f.neighbour) == j) {
        own += area;
        if (std::abs(nrm.z) <= side_sin) walls += area;
        if (nrm.z > side_sin && nrm.z < stacked_cos && area > 0)
          pm.sloped_roof.push_back({nrm, m.vertices[f.rings[0][0]], area});
        if (nrm.z <= -stacked_cos && m.is_label(f.semantic, "GroundSurface")) ground_down += area;
        continue;
      }
      if (!(area > 0)) continue;
      auto& slot = acc[static_cast<uint32_t>(f.neighbour)][kind_name(nrm.z, stacked_cos, side_sin)];
      slot.first += area;
      slot.second += nrm.z > 0 ? -area : area;  // outward normal up: the other part lies above
    }
    for (const auto& [other, kinds] : acc) pm.contacts.push_back(contact_from(other, kinds));
    pm.wall_share = own > 0 ? walls / own : 0.0;
    pm.flat_top = pm.footprint_area > 0 ? std::min(1.0, flat_up / pm.footprint_area) : 0.0;
    // On the ground: the input says so (most of its bottom on the GroundSurface, wherever the
    // terrain is: a wing on a slope stands higher than the main block), or it starts at the
    // building's lowest point.
    pm.grounded = pm.footprint_area > 0 && ground_down >= 0.5 * pm.footprint_area;
  }
  for (auto& pm : L.parts) pm.grounded = pm.grounded || pm.z_min <= ground + p.ground_tolerance;
  group_masses(L, meshes, p);
  assign_roles(L, p);
  return L;
}

namespace {

// Tiers: the longest chain of stacked contacts between masses, + 1 (masses in order of z_min: an
// edge goes up); a roof or a rooftop unit is no tier.
int tiers_of(const LevelMassing& L) {
  const size_t nm = L.masses.size();
  if (nm == 0) return 0;
  std::vector<size_t> order(nm);
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return L.masses[a].z_min < L.masses[b].z_min; });
  std::vector<int> chain;
  chain.resize(nm, 1);
  int tiers = 1;
  for (size_t i : order) {
    for (const Contact& c : L.masses[i].contacts)
      if (c.kind == "stacked" && c.above == 1 && L.masses[c.other].z_min < L.masses[i].z_min) {
        const bool tier = L.masses[i].role != "rooftop";
        chain[i] = std::max(chain[i], chain[c.other] + (tier ? 1 : 0));
      }
    tiers = std::max(tiers, chain[i]);
  }
  return tiers;
}

}  // namespace

void finish_massing(BuildingMassing& m, const MassingParams& p) {
  m.features = {};
  m.footprint.clear();
  if (m.levels.empty()) return;
  const LevelMassing& L = m.levels[analysis_index(m, p.level)];
  MassingFeatures& f = m.features;
  f.valid = true;
  f.level = L.threshold;
  const size_t n = L.parts.size();
  // Counts of masses (docs/massing.md, "Building features").
  for (const auto& mm : L.masses) {
    f.setbacks += mm.role == "setback";
    f.wings += mm.role == "wing";
    f.annexes += mm.role == "annex";
    f.rooftop_units += mm.role == "rooftop";
    f.tower_on_podium = f.tower_on_podium || mm.role == "podium";
  }
  f.tiers = tiers_of(L);
  // Graph: undirected edges, components, independent cycles.
  mc::UnionFind graph(n);
  for (size_t i = 0; i < n; ++i)
    for (const Contact& c : L.parts[i].contacts)
      if (c.other > i && c.other < n) {
        ++f.edges;
        graph.link(static_cast<uint32_t>(i), static_cast<uint32_t>(c.other));
      }
  int components = 0;
  for (uint32_t i = 0; i < n; ++i) components += graph.find(i) == i;
  f.cycles = f.edges - static_cast<int>(n) + components;
  // Footprint union and courtyards (its holes).
  std::vector<Polygon2> polys;
  for (const auto& pm : L.parts)
    for (const auto& poly : pm.footprint) polys.push_back(poly);
  bool ok = false;
  m.footprint = union_of(polys, ok);
  for (const auto& poly : m.footprint)
    for (size_t r = 1; r < poly.size(); ++r)
      f.courtyards += std::abs(ring_signed_area(poly[r])) >= p.courtyard_min_area;
}

void to_file(BuildingMassing& m, const WorkingFrame& frame) {
  if (frame.identity()) return;
  auto map = [&](mc::io::MultiPolygon2& mp) {
    for (auto& poly : mp)
      for (auto& ring : poly)
        for (auto& p : ring) {
          const Vec3 f = frame.to_file({p[0], p[1], 0});
          p = {f.x, f.y};
        }
  };
  map(m.footprint);
  for (auto& L : m.levels)
    for (auto& pm : L.parts) map(pm.footprint);
}

void add_part_attributes(json& a, const LevelMassing& L, size_t j, const std::string& building) {
  const PartMassing& pm = L.parts[j];
  a["morphcut_role"] = pm.role;  // its mass's
  a["morphcut_mass"] = pm.mass;
  a["morphcut_piece"] = pm.piece;
  a["morphcut_z_min"] = rounded(pm.z_min, 1e-6);
  a["morphcut_z_max"] = rounded(pm.z_max, 1e-6);
  a["morphcut_footprint_area"] = rounded(pm.footprint_area, 1e-6);
  a["morphcut_hull_volume"] = rounded(pm.hull_volume, 1e-6);
  a["morphcut_grounded"] = pm.grounded;
  json contacts = json::array();
  for (const Contact& c : pm.contacts)
    contacts.push_back({{"part", part_name(building, L.index, c.other)},
                        {"kind", c.kind},
                        {"position", position(c.above)},
                        {"shared_area", rounded(c.area, 1e-6)}});
  a["morphcut_contacts"] = std::move(contacts);
}

const std::vector<std::string>& building_attribute_names() {
  static const std::vector<std::string> names = {
      "morphcut_massing_level", "morphcut_tiers",         "morphcut_setbacks",   "morphcut_wings",
      "morphcut_annexes",       "morphcut_rooftop_units", "morphcut_courtyards", "morphcut_tower_on_podium",
      "morphcut_graph_edges",   "morphcut_graph_cycles"};
  return names;
}

const std::vector<std::string>& massing_columns() { return building_attribute_names(); }

void add_building_attributes(json& a, const BuildingMassing& m) {
  const MassingFeatures& f = m.features;
  if (!f.valid) return;
  a["morphcut_massing_level"] = f.level;
  a["morphcut_tiers"] = f.tiers;
  a["morphcut_setbacks"] = f.setbacks;
  a["morphcut_wings"] = f.wings;
  a["morphcut_annexes"] = f.annexes;
  a["morphcut_rooftop_units"] = f.rooftop_units;
  a["morphcut_courtyards"] = f.courtyards;
  a["morphcut_tower_on_podium"] = f.tower_on_podium;
  a["morphcut_graph_edges"] = f.edges;
  a["morphcut_graph_cycles"] = f.cycles;
}

json massing_to_json(const BuildingMassing& m) {
  json levels = json::array();
  for (const auto& L : m.levels) {
    json parts = json::array();
    for (const auto& pm : L.parts) {
      json contacts = json::array();
      for (const auto& c : pm.contacts) contacts.push_back({c.other, c.area, c.kind, c.above});
      parts.push_back({{"z", {pm.z_min, pm.z_max}},
                       {"fa", pm.footprint_area},
                       {"w", pm.width},
                       {"l", pm.length},
                       {"ws", pm.wall_share},
                       {"m", pm.mass},
                       {"pc", pm.piece},
                       {"v", {pm.volume, pm.hull_volume, pm.convexity}},
                       {"g", pm.grounded},
                       {"r", pm.role},
                       {"c", contacts},
                       {"f", rings_json(pm.footprint)}});
    }
    json masses = json::array();
    for (const auto& mm : L.masses) {
      json contacts = json::array();
      for (const auto& c : mm.contacts) contacts.push_back({c.other, c.area, c.kind, c.above});
      masses.push_back({{"p", mm.parts},
                        {"z", {mm.z_min, mm.z_max}},
                        {"v", {mm.volume, mm.hull_volume}},
                        {"fa", mm.footprint_area},
                        {"wl", {mm.width, mm.length}},
                        {"g", mm.grounded},
                        {"r", mm.role},
                        {"c", contacts}});
    }
    levels.push_back({{"i", L.index}, {"t", L.threshold}, {"p", parts}, {"m", masses}});
  }
  const MassingFeatures& f = m.features;
  return {{"levels", levels},
          {"features",
           {f.valid, f.level, f.tiers, f.setbacks, f.wings, f.annexes, f.rooftop_units, f.courtyards,
            f.tower_on_podium, f.edges, f.cycles}},
          {"footprint", rings_json(m.footprint)}};
}

void massing_from_json(const json& j, BuildingMassing& m) {
  m = {};
  for (const auto& lj : j.at("levels")) {
    LevelMassing L;
    L.index = lj.at("i").get<size_t>();
    L.threshold = lj.at("t").get<double>();
    for (const auto& pj : lj.at("p")) {
      PartMassing pm;
      pm.z_min = pj.at("z")[0].get<double>();
      pm.z_max = pj.at("z")[1].get<double>();
      pm.footprint_area = pj.at("fa").get<double>();
      pm.width = pj.at("w").get<double>();
      pm.length = pj.at("l").get<double>();
      pm.wall_share = pj.at("ws").get<double>();
      pm.mass = pj.at("m").get<int>();
      pm.piece = pj.at("pc").get<std::string>();
      pm.volume = pj.at("v")[0].get<double>();
      pm.hull_volume = pj.at("v")[1].get<double>();
      pm.convexity = pj.at("v")[2].get<double>();
      pm.grounded = pj.at("g").get<bool>();
      pm.role = pj.at("r").get<std::string>();
      for (const auto& cj : pj.at("c"))
        pm.contacts.push_back(
            {cj[0].get<uint32_t>(), cj[1].get<double>(), cj[2].get<std::string>(), cj[3].get<int>()});
      pm.footprint = rings_from_json(pj.at("f"));
      L.parts.push_back(std::move(pm));
    }
    for (const auto& mj : lj.at("m")) {
      MassMassing mm;
      mm.parts = mj.at("p").get<std::vector<uint32_t>>();
      mm.z_min = mj.at("z")[0].get<double>();
      mm.z_max = mj.at("z")[1].get<double>();
      mm.volume = mj.at("v")[0].get<double>();
      mm.hull_volume = mj.at("v")[1].get<double>();
      mm.footprint_area = mj.at("fa").get<double>();
      mm.width = mj.at("wl")[0].get<double>();
      mm.length = mj.at("wl")[1].get<double>();
      mm.grounded = mj.at("g").get<bool>();
      mm.role = mj.at("r").get<std::string>();
      for (const auto& cj : mj.at("c"))
        mm.contacts.push_back(
            {cj[0].get<uint32_t>(), cj[1].get<double>(), cj[2].get<std::string>(), cj[3].get<int>()});
      L.masses.push_back(std::move(mm));
    }
    m.levels.push_back(std::move(L));
  }
  const json& f = j.at("features");
  MassingFeatures& x = m.features;
  x.valid = f[0].get<bool>();
  x.level = f[1].get<double>();
  x.tiers = f[2].get<int>();
  x.setbacks = f[3].get<int>();
  x.wings = f[4].get<int>();
  x.annexes = f[5].get<int>();
  x.rooftop_units = f[6].get<int>();
  x.courtyards = f[7].get<int>();
  x.tower_on_podium = f[8].get<bool>();
  x.edges = f[9].get<int>();
  x.cycles = f[10].get<int>();
  m.footprint = rings_from_json(j.at("footprint"));
}

json graph_json(const std::string& building, const std::string& status, const BuildingMassing& m) {
  json levels = json::array();
  for (const auto& L : m.levels) {
    json nodes = json::array(), edges = json::array();
    for (size_t j = 0; j < L.parts.size(); ++j) {
      const PartMassing& pm = L.parts[j];
      nodes.push_back({{"id", part_name(building, L.index, j)},
                       {"index", j},
                       {"role", pm.role},
                       {"mass", pm.mass},
                       {"piece", pm.piece},
                       {"z_min", rounded(pm.z_min, 1e-6)},
                       {"z_max", rounded(pm.z_max, 1e-6)},
                       {"footprint_area", rounded(pm.footprint_area, 1e-6)},
                       {"volume", rounded(pm.volume, 1e-6)},
                       {"hull_volume", rounded(pm.hull_volume, 1e-6)},
                       {"convexity", rounded(pm.convexity, 1e-9)},
                       {"grounded", pm.grounded}});
      for (const Contact& c : pm.contacts) {
        if (c.other <= j) continue;  // each pair once, from its lower index
        json e = {{"source", part_name(building, L.index, j)},
                  {"target", part_name(building, L.index, c.other)},
                  {"kind", c.kind},
                  {"shared_area", rounded(c.area, 1e-6)}};
        if (c.above != 0) e["upper"] = part_name(building, L.index, c.above > 0 ? j : c.other);
        edges.push_back(std::move(e));
      }
    }
    json masses = json::array();
    for (size_t k = 0; k < L.masses.size(); ++k) {
      const MassMassing& mm = L.masses[k];
      masses.push_back({{"mass", k},
                        {"role", mm.role},
                        {"parts", mm.parts},
                        {"z_min", rounded(mm.z_min, 1e-6)},
                        {"z_max", rounded(mm.z_max, 1e-6)},
                        {"footprint_area", rounded(mm.footprint_area, 1e-6)},
                        {"volume", rounded(mm.volume, 1e-6)},
                        {"grounded", mm.grounded}});
    }
    levels.push_back({{"threshold", L.threshold},
                      {"index", L.index},
                      {"nodes", nodes},
                      {"edges", edges},
                      {"masses", masses}});
  }
  json features = nullptr;
  if (m.features.valid) {
    features = json::object();
    add_building_attributes(features, m);
  }
  return {{"id", building}, {"status", status}, {"features", features}, {"levels", levels}};
}

}  // namespace mc::massing
