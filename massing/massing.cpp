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

namespace mc::massing {

using mc::io::MultiPolygon2;
using mc::io::Polygon2;
using mc::io::Ring2;
using nlohmann::json;
using Pt = std::array<double, 2>;

namespace {

constexpr double kPi = 3.14159265358979323846;

double rounded(double v, double step) { return std::isfinite(v) ? std::round(v / step) * step : v; }

// Coordinates on a 1e-6 grid before any union: shared vertices of neighbouring parts are then
// exactly equal, and the result does not depend on the last bits of a projection.
double snap(double v) { return std::round(v * 1e6) / 1e6; }

double cross2(const Pt& o, const Pt& a, const Pt& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

double ring_signed_area(const Ring2& r) {
  double s = 0;
  for (size_t i = 0, n = r.size(); i < n; ++i) {
    const Pt& a = r[i];
    const Pt& b = r[(i + 1) % n];
    s += a[0] * b[1] - b[0] * a[1];
  }
  return s / 2;
}

double polygon_area(const Polygon2& p) {
  double a = 0;
  for (size_t i = 0; i < p.size(); ++i) a += (i == 0 ? 1 : -1) * std::abs(ring_signed_area(p[i]));
  return a;
}

double multipolygon_area(const MultiPolygon2& m) {
  double a = 0;
  for (const auto& p : m) a += polygon_area(p);
  return a;
}

// Smallest distance between two parallel lines enclosing a convex polygon (over its edges).
double caliper_width(const Ring2& hull) {
  if (hull.size() < 3) return 0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < hull.size(); ++i) {
    const Pt& a = hull[i];
    const Pt& b = hull[(i + 1) % hull.size()];
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (len <= 0) continue;
    double far = 0;
    for (const Pt& q : hull) far = std::max(far, std::abs(cross2(a, b, q)) / len);
    best = std::min(best, far);
  }
  return std::isfinite(best) ? best : 0;
}

using mc::io::to_ogr;

Polygon2 from_ogr(const OGRPolygon& p) {
  Polygon2 out;
  auto ring = [](const OGRLinearRing* r) {
    Ring2 x;
    const int n = r->getNumPoints();
    for (int i = 0; i + 1 < n; ++i) x.push_back({r->getX(i), r->getY(i)});
    return x;
  };
  if (const OGRLinearRing* ext = p.getExteriorRing()) out.push_back(ring(ext));
  for (int i = 0; i < p.getNumInteriorRings(); ++i) out.push_back(ring(p.getInteriorRing(i)));
  return out;
}

void collect(const OGRGeometry* g, MultiPolygon2& out) {
  if (!g) return;
  const OGRwkbGeometryType t = wkbFlatten(g->getGeometryType());
  if (t == wkbPolygon) {
    out.push_back(from_ogr(*g->toPolygon()));
  } else if (t == wkbMultiPolygon || t == wkbGeometryCollection) {
    const auto* c = g->toGeometryCollection();
    for (int i = 0; i < c->getNumGeometries(); ++i) collect(c->getGeometryRef(i), out);
  }
}

// Exact union of polygons (GEOS through OGR); empty on failure.
MultiPolygon2 union_of(const std::vector<Polygon2>& polys, bool& ok) {
  // Invalid footprints are expected (faces projected edge-on) and repaired below: GEOS's notices
  // about them would only be noise on the user's stderr. The handler stack is per thread.
  struct QuietGdal {
    QuietGdal() { CPLPushErrorHandler(CPLQuietErrorHandler); }
    ~QuietGdal() { CPLPopErrorHandler(); }
  } quiet;
  OGRMultiPolygon mp;
  for (const auto& p : polys) {
    OGRPolygon g = to_ogr(p);
    if (g.IsEmpty()) continue;
    if (!g.IsValid()) {
      std::unique_ptr<OGRGeometry> fixed(g.Buffer(0));
      MultiPolygon2 parts;
      collect(fixed.get(), parts);
      for (const auto& q : parts) {
        OGRPolygon h = to_ogr(q);
        if (!h.IsEmpty()) mp.addGeometry(&h);
      }
      continue;
    }
    mp.addGeometry(&g);
  }
  MultiPolygon2 out;
  ok = true;
  if (mp.IsEmpty()) return out;
  std::unique_ptr<OGRGeometry> u(mp.UnionCascaded());
  if (!u) {
    ok = false;
    return out;
  }
  collect(u.get(), out);
  // Canonical order (GEOS's output order is deterministic, but make it independent of it).
  for (auto& poly : out)
    for (auto& r : poly) {
      if (r.empty()) continue;
      std::rotate(r.begin(), std::min_element(r.begin(), r.end()), r.end());
    }
  std::sort(out.begin(), out.end());
  return out;
}

// Vector area (half the sum of cross products) of a 3D ring.
Vec3 vector_area(const PolygonMesh& m, const std::vector<uint32_t>& ring) {
  Vec3 s{};
  for (size_t i = 0, n = ring.size(); i < n; ++i)
    s += cross(m.vertices[ring[i]], m.vertices[ring[(i + 1) % n]]);
  return s * 0.5;
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

// Roles (docs/massing.md §Roles): ordered rules, the first that applies gives a part its role.
void assign_roles(LevelMassing& L, const MassingParams& p) {
  auto& P = L.parts;
  const size_t n = P.size();
  std::vector<size_t> by_volume(n);
  std::iota(by_volume.begin(), by_volume.end(), size_t{0});
  std::stable_sort(by_volume.begin(), by_volume.end(),
                   [&](size_t a, size_t b) { return P[a].volume > P[b].volume; });
  auto height = [&](size_t i) { return P[i].z_max - P[i].z_min; };

  // 1. podium and tower: a raised part t stacked on the largest grounded part q, covering a small
  //    share of q's footprint, slender, at least as tall as q and not a rooftop unit by volume.
  size_t largest_grounded = n;
  for (size_t i : by_volume)
    if (P[i].grounded) {
      largest_grounded = i;
      break;
    }
  for (size_t t : by_volume) {
    if (P[t].grounded || !P[t].role.empty()) continue;
    for (const Contact& c : P[t].contacts) {
      if (c.kind != "stacked" || c.above != 1) continue;
      const size_t q = c.other;
      if (q != largest_grounded) continue;
      if (P[t].volume <= p.rooftop_max_share * P[q].volume) continue;
      if (c.area > p.podium_max_roof_share * P[q].footprint_area) continue;
      if (height(t) < p.tower_min_slenderness * P[t].width) continue;
      if (height(t) < p.tower_min_height_ratio * height(q)) continue;
      P[q].role = "podium";
      P[t].role = "tower";
      break;
    }
  }
  // 2. main: the largest grounded part left.
  size_t main = n;
  for (size_t i : by_volume)
    if (P[i].grounded && P[i].role.empty()) {
      main = i;
      P[i].role = "main";
      break;
    }
  double reference = main < n ? P[main].volume : 0;
  if (main == n)
    for (size_t i : by_volume)
      if (P[i].role == "podium") {
        reference = P[i].volume;
        break;
      }
  // 3./4. the other grounded parts: wing when substantial, else annex.
  for (size_t i = 0; i < n; ++i)
    if (P[i].grounded && P[i].role.empty())
      P[i].role = P[i].volume >= p.wing_min_share * reference ? "wing" : "annex";
  // 5. roof: a raised part that is a pitched-roof wedge, sawtooth or slab cut off the storeys it
  //    rests on: it fills at most roof_max_fill of its footprint x height and its largest contact
  //    below is stacked and covers at least 0.8 of its footprint. Not a stepped-back storey (a
  //    setback) nor a unit on the roof (docs/massing.md: judged on rendered 3D BAG buildings).
  for (size_t i = 0; i < n; ++i) {
    if (!P[i].role.empty() || !(P[i].footprint_area > 0) || !(height(i) > 0)) continue;
    const Contact* below = nullptr;
    for (const Contact& c : P[i].contacts)
      if (c.above == 1 && (!below || c.area > below->area)) below = &c;
    if (!below || below->kind != "stacked" || below->area < 0.8 * P[i].footprint_area) continue;
    if (P[i].volume <= p.roof_max_fill * P[i].footprint_area * height(i)) P[i].role = "roof";
  }
  // 6./7. other raised parts: rooftop when small beside what carries them, else setback.
  for (size_t i = 0; i < n; ++i) {
    if (!P[i].role.empty()) continue;
    // Support: the neighbour it rests on with the largest shared area (stacked or inclined
    // contact, this part above); else the neighbour it shares most with; else the largest part.
    long s = -1;
    double best = -1;
    for (const Contact& c : P[i].contacts)
      if (c.above == 1 && c.area > best) best = c.area, s = static_cast<long>(c.other);
    if (s < 0)
      for (const Contact& c : P[i].contacts)
        if (c.area > best) best = c.area, s = static_cast<long>(c.other);
    const double support = s >= 0 ? P[static_cast<size_t>(s)].volume : (n ? P[by_volume[0]].volume : 0);
    P[i].role = P[i].volume <= p.rooftop_max_share * support ? "rooftop" : "setback";
  }
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
    pm.width = caliper_width(mc::convex_hull_2d(outer));
    // Contacts: shared faces by neighbour and kind.
    std::map<uint32_t, std::map<std::string, std::pair<double, double>>>
        acc;  // other -> kind -> (area, signed up-area)
    for (const Polygon& f : m.faces) {
      if (f.neighbour < 0 || static_cast<size_t>(f.neighbour) >= n || static_cast<size_t>(f.neighbour) == j)
        continue;
      const auto [area, nrm] = face_area(m, f);
      if (!(area > 0)) continue;
      auto& slot = acc[static_cast<uint32_t>(f.neighbour)][kind_name(nrm.z, stacked_cos, side_sin)];
      slot.first += area;
      slot.second += nrm.z > 0 ? area : -area;  // outward normal up: the other part lies above
    }
    for (const auto& [other, kinds] : acc) {
      Contact c;
      c.other = other;
      double best = -1;
      for (const auto& [kind, v] : kinds) {
        c.area += v.first;
        if (v.first > best) best = v.first, c.kind = kind;
      }
      if (c.kind != "side") {
        const double up = kinds.at(c.kind).second;
        c.above = up > 0 ? -1 : up < 0 ? 1 : 0;
      }
      pm.contacts.push_back(std::move(c));
    }
  }
  for (auto& pm : L.parts) pm.grounded = pm.z_min <= ground + p.ground_tolerance;
  assign_roles(L, p);
  return L;
}

void finish_massing(BuildingMassing& m, const MassingParams& p) {
  m.features = {};
  m.footprint.clear();
  if (m.levels.empty()) return;
  const LevelMassing& L = m.levels[analysis_index(m, p.level)];
  MassingFeatures& f = m.features;
  f.valid = true;
  f.level = L.threshold;
  const size_t n = L.parts.size();
  for (const auto& pm : L.parts) {
    f.setbacks += pm.role == "setback";
    f.wings += pm.role == "wing";
    f.annexes += pm.role == "annex";
    f.rooftop_units += pm.role == "rooftop";
    f.tower_on_podium = f.tower_on_podium || pm.role == "podium";
  }
  // Tiers: the longest chain of stacked contacts, + 1 (parts in order of z_min: an edge goes up).
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return L.parts[a].z_min < L.parts[b].z_min; });
  std::vector<int> chain(n, 1);
  for (size_t i : order)
    for (const Contact& c : L.parts[i].contacts)
      if (c.kind == "stacked" && c.above == 1 && L.parts[c.other].z_min < L.parts[i].z_min)
        chain[i] =
            std::max(chain[i], chain[c.other] + (L.parts[i].role == "roof" ? 0 : 1));  // a roof is no tier
  for (int c : chain) f.tiers = std::max(f.tiers, c);
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
  a["morphcut_role"] = pm.role;
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
                       {"v", {pm.volume, pm.hull_volume, pm.convexity}},
                       {"g", pm.grounded},
                       {"r", pm.role},
                       {"c", contacts},
                       {"f", rings_json(pm.footprint)}});
    }
    levels.push_back({{"i", L.index}, {"t", L.threshold}, {"p", parts}});
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
    levels.push_back({{"threshold", L.threshold}, {"index", L.index}, {"nodes", nodes}, {"edges", edges}});
  }
  json features = nullptr;
  if (m.features.valid) {
    features = json::object();
    add_building_attributes(features, m);
  }
  return {{"id", building}, {"status", status}, {"features", features}, {"levels", levels}};
}

}  // namespace mc::massing
