// CityGML -> CityJSON mapping of a building. Geometry per LoD: the object's lodXSolid when it has
// one (semantics from the boundary surfaces whose polygons it uses, usually via xlink), else one
// MultiSurface of its own lodXMultiSurface polygons plus those of its boundary surfaces.
#include "io/citygml_building.hpp"

#include <charconv>
#include <map>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "io/citygml_geometry.hpp"
#include "io/citygml_xml.hpp"

namespace mc::io::citygml {

using nlohmann::json;
using namespace gmlxml;

namespace {

// CityGML thematic surfaces and openings -> CityJSON 2.0 semantic surface types.
std::optional<std::string> semantic_type(std::string_view name) {
  static const std::unordered_map<std::string_view, std::string> types = {
      {"RoofSurface", "RoofSurface"},
      {"WallSurface", "WallSurface"},
      {"GroundSurface", "GroundSurface"},
      {"ClosureSurface", "ClosureSurface"},
      {"OuterCeilingSurface", "OuterCeilingSurface"},
      {"OuterFloorSurface", "OuterFloorSurface"},
      {"FloorSurface", "FloorSurface"},
      {"CeilingSurface", "CeilingSurface"},
      {"InteriorWallSurface", "InteriorWallSurface"},
      {"Window", "Window"},
      {"Door", "Door"},
      {"WindowSurface", "Window"},  // CityGML 3.0 filling surfaces
      {"DoorSurface", "Door"},
  };
  auto it = types.find(name);
  if (it == types.end()) return std::nullopt;
  return it->second;
}

// "lod2Solid" -> {2, "Solid"}; "lod0FootPrint" -> {0, "FootPrint"}; no match -> lod -1.
std::pair<int, std::string_view> lod_property(std::string_view name) {
  if (name.size() < 5 || name.substr(0, 3) != "lod" || name[3] < '0' || name[3] > '4') return {-1, {}};
  return {name[3] - '0', name.substr(4)};
}

// Typed values of the attributes CityJSON documents as numbers.
json typed(std::string_view name, const std::string& s) {
  static const std::unordered_set<std::string_view> integers = {"yearOfConstruction", "yearOfDemolition",
                                                                "storeysAboveGround", "storeysBelowGround"};
  static const std::unordered_set<std::string_view> numbers = {"measuredHeight", "storeyHeightsAboveGround",
                                                               "storeyHeightsBelowGround"};
  if (integers.count(name)) {
    long long v = 0;
    auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (r.ec == std::errc() && r.ptr == s.data() + s.size()) return v;
  } else if (numbers.count(name)) {
    std::vector<double> vs;
    const char* p = s.data();
    const char* e = s.data() + s.size();
    while (p < e) {
      while (p < e && *p == ' ') ++p;
      if (p == e) break;
      double v = 0;
      auto r = std::from_chars(p, e, v);
      if (r.ec != std::errc()) return s;
      vs.push_back(v);
      p = r.ptr;
    }
    if (vs.size() == 1) return vs[0];
    if (!vs.empty()) return vs;
  }
  return s;
}

// Repeated CityGML properties (two gml:name, three bldg:function) become arrays.
void add_attribute(json& attrs, const std::string& key, json value) {
  auto it = attrs.find(key);
  if (it == attrs.end()) {
    attrs[key] = std::move(value);
  } else {
    if (!it->is_array()) *it = json::array({*it});
    it->push_back(std::move(value));
  }
}

// gen:stringAttribute name="x"><gen:value>..  (1.0/2.0), gen:StringAttribute><gen:name>x</gen:name>
// <gen:value>..  (3.0, inside core:genericAttribute); sets become nested objects.
void generic_attribute(const xmlNode* el, json& attrs) {
  const std::string_view kind = local(el);
  if (kind == "genericAttribute") {
    for (const xmlNode* c = first_child(el); c; c = next_sibling(c)) generic_attribute(c, attrs);
    return;
  }
  std::string name = attr(el, "name");
  const xmlNode* value = nullptr;
  std::vector<const xmlNode*> members;
  for (const xmlNode* c = first_child(el); c; c = next_sibling(c)) {
    if (local(c) == "name" && name.empty()) name = trim(text(c));
    else if (local(c) == "value") value = c;
    else members.push_back(c);
  }
  if (name.empty()) return;
  std::string lower(kind);
  for (auto& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (lower == "genericattributeset") {
    json set = json::object();
    for (const xmlNode* m : members) generic_attribute(m, set);
    add_attribute(attrs, name, std::move(set));
    return;
  }
  if (!value) return;
  const std::string s = trim(text(value));
  if (lower == "intattribute" || lower == "doubleattribute" || lower == "measureattribute") {
    double v = 0;
    auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    if (r.ec == std::errc() && r.ptr == s.data() + s.size()) {
      if (lower == "intattribute" && v == static_cast<double>(static_cast<long long>(v)))
        add_attribute(attrs, name, static_cast<long long>(v));
      else add_attribute(attrs, name, v);
      return;
    }
  }
  add_attribute(attrs, name, s);
}

struct SemanticPolygon {
  Polygon polygon;
  std::optional<std::string> type;
};

// What one object (Building or BuildingPart) has at one LoD.
struct LodContent {
  std::vector<Geometry> own;              // lodXSolid, lodXMultiSurface, ...
  std::vector<SemanticPolygon> boundary;  // polygons of its boundary surfaces and openings
};

class Converter {
 public:
  Converter(const xmlNode* building, std::string id, const RemoteGeometry* remote)
      : id_(std::move(id)), geo_(building, remote) {}

  ConvertedBuilding run(const xmlNode* building) {
    ConvertedBuilding out;
    out.feature.id = id_;
    out.feature.objects = json::object();
    object(building, "Building", id_, "", out.feature);
    Feature& f = out.feature;
    std::vector<std::string> problems;
    if (!geo_.fatal().empty()) {
      for (auto& [oid, obj] : f.objects.items()) obj.erase("geometry");
      geo_.vertices().clear();
      problems.push_back(id_ + ": " + geo_.fatal() + "; the building's geometry is not read");
    }
    for (auto& n : notes_) problems.push_back(std::move(n));
    for (auto& n : geo_.notes()) problems.push_back(id_ + ": " + n);
    f.problems = std::move(problems);
    f.vertices = std::move(geo_.vertices());
    out.srs_name = geo_.srs_name();
    out.srs_names = geo_.srs_names();
    out.ade = std::move(ade_);
    return out;
  }

 private:
  void object(const xmlNode* el, const std::string& type, const std::string& id, const std::string& parent,
              Feature& f) {
    json obj = {{"type", type}};
    json attrs = json::object();
    json children = json::array();
    std::map<int, LodContent> lods;
    std::vector<int> implicit;
    int parts = 0;
    for (const xmlNode* c = first_child(el); c; c = next_sibling(c)) {
      const std::string_view name = local(c), uri = ns_uri(c);
      if (is_gml_ns(uri)) {
        if (name == "name" || name == "description") add_attribute(attrs, std::string(name), trim(text(c)));
        continue;  // gml:boundedBy (envelope) and the rest: nothing to carry
      }
      if (is_generics_ns(uri) || (is_citygml_ns(uri) && name == "genericAttribute")) {  // 1.0/2.0 | 3.0
        generic_attribute(c, attrs);
        continue;
      }
      if (!is_citygml_ns(uri)) {
        ade_.add(qualified_name(c), uri);  // an ADE property (or an unqualified element): not read
        continue;
      }
      if (auto [lod, kind] = lod_property(name); lod >= 0) {
        if (kind == "Solid" || kind == "MultiSurface" || kind == "Geometry" || kind == "FootPrint" ||
            kind == "RoofEdge") {
          if (auto g = geo_.read(c)) lods[lod].own.push_back(std::move(*g));
        } else if (kind == "ImplicitRepresentation") {
          implicit.push_back(lod);
        }
        continue;  // lodXMultiCurve, lodXTerrainIntersection(Curve): curves, not carried
      }
      if (name == "boundedBy" || name == "boundary") {
        if (const xmlNode* s = geo_.content(c)) thematic_surface(s, lods);
      } else if (name == "consistsOfBuildingPart" || name == "buildingPart") {
        const xmlNode* p = geo_.content(c);
        if (!p || local(p) != "BuildingPart") continue;
        std::string pid = gml_id(p);
        if (pid.empty()) pid = id + "-part-" + std::to_string(++parts);
        if (f.objects.contains(pid)) {
          notes_.push_back(id_ + ": BuildingPart \"" + pid + "\" appears twice; the second is skipped");
          continue;
        }
        object(p, "BuildingPart", pid, id, f);
        children.push_back(pid);
      } else if (name.rfind("adeOf", 0) == 0) {  // CityGML 3.0's hook for ADE properties
        for (const xmlNode* a = first_child(c); a; a = next_sibling(a))
          if (!is_citygml_ns(ns_uri(a))) ade_.add(qualified_name(a), ns_uri(a));
      } else if (!first_child(c) && href(c).empty()) {
        add_attribute(attrs, std::string(name), typed(name, trim(text(c))));
      }
      // Everything else (address, appearance, interiorRoom, installations, ...) is not carried.
    }
    for (int lod : implicit)
      notes_.push_back(id + ": lod" + std::to_string(lod) +
                       "ImplicitRepresentation (implicit geometry) is not supported; not read");
    if (!attrs.empty()) obj["attributes"] = std::move(attrs);
    if (!parent.empty()) obj["parents"] = json::array({parent});
    if (!children.empty()) obj["children"] = std::move(children);
    json geometry = geometries(id, lods);
    if (!geometry.empty()) obj["geometry"] = std::move(geometry);
    f.objects[id] = std::move(obj);
  }

  // A boundary surface (or opening) and its openings: every polygon with its semantic type.
  void thematic_surface(const xmlNode* el, std::map<int, LodContent>& lods) {
    const std::optional<std::string> type = semantic_type(local(el));
    for (const xmlNode* c = first_child(el); c; c = next_sibling(c)) {
      const std::string_view name = local(c);
      if (is_ade_ns(ns_uri(c))) {
        ade_.add(qualified_name(c), ns_uri(c));
        continue;
      }
      if (auto [lod, kind] = lod_property(name); lod >= 0 && (kind == "MultiSurface" || kind == "Geometry")) {
        for (auto& p : geo_.read_surfaces(c)) lods[lod].boundary.push_back({std::move(p), type});
      } else if (name == "opening" || name == "fillingSurface") {
        if (const xmlNode* o = geo_.content(c)) thematic_surface(o, lods);
      }
    }
  }

  // CityJSON "lod": CityGML 2.0's lod4 becomes "3" (CityJSON stops at 3) unless lod3 exists.
  json geometries(const std::string& id, const std::map<int, LodContent>& lods) {
    std::unordered_map<const xmlNode*, std::string> semantic_of;
    for (const auto& [lod, content] : lods)
      for (const auto& sp : content.boundary)
        if (sp.type) semantic_of.emplace(sp.polygon.source, *sp.type);
    json out = json::array();
    for (const auto& [lod, content] : lods) {
      if (lod == 4 && lods.count(3)) {
        notes_.push_back(id + ": lod4 geometry not carried (CityJSON has no LoD 4 and lod3 exists)");
        continue;
      }
      const std::string lod_text = std::to_string(std::min(lod, 3));
      size_t solids = 0, dropped = 0;
      std::unordered_set<const xmlNode*> used;
      for (const auto& g : content.own)
        if (g.is_solid()) {
          ++solids;
          out.push_back(encode(g, lod_text, semantic_of));
          for (const auto& s : g.solids)
            for (const auto& shell : s.shells)
              for (const auto& p : shell) used.insert(p.source);
        }
      if (solids) {
        // The solid is the building's volume at this LoD; other polygons would double its faces.
        for (const auto& g : content.own)
          if (!g.is_solid())
            for (const auto& p : g.surfaces) dropped += !used.count(p.source);
        for (const auto& sp : content.boundary) dropped += !used.count(sp.polygon.source);
        if (dropped)
          notes_.push_back(id + ": " + std::to_string(dropped) + " lod" + std::to_string(lod) +
                           " surface(s) outside the lod" + std::to_string(lod) + "Solid not carried");
        continue;
      }
      Geometry ms;
      ms.type = content.own.size() == 1 && content.boundary.empty() ? content.own[0].type : "MultiSurface";
      std::unordered_set<const xmlNode*> seen;
      for (const auto& g : content.own)
        for (const auto& p : g.surfaces)
          if (seen.insert(p.source).second) ms.surfaces.push_back(p);
      for (const auto& sp : content.boundary)
        if (seen.insert(sp.polygon.source).second) ms.surfaces.push_back(sp.polygon);
      if (!ms.surfaces.empty()) out.push_back(encode(ms, lod_text, semantic_of));
    }
    return out;
  }

  static json encode(const Geometry& g, const std::string& lod,
                     const std::unordered_map<const xmlNode*, std::string>& semantic_of) {
    json surfaces = json::array();
    std::unordered_map<std::string, size_t> index;
    bool any = false;
    auto surface = [](const Polygon& p) {
      json s = json::array();
      for (const auto& r : p.rings) s.push_back(r);
      return s;
    };
    auto value = [&](const Polygon& p) -> json {
      auto it = semantic_of.find(p.source);
      if (it == semantic_of.end()) return nullptr;
      any = true;
      auto [at, added] = index.emplace(it->second, index.size());
      if (added) surfaces.push_back({{"type", it->second}});
      return at->second;
    };
    auto shell_json = [&](const std::vector<Polygon>& shell, json& values) {
      json b = json::array();
      for (const auto& p : shell) {
        b.push_back(surface(p));
        values.push_back(value(p));
      }
      return b;
    };
    json boundaries = json::array(), values = json::array();
    if (g.type == "MultiSurface" || g.type == "CompositeSurface") {
      boundaries = shell_json(g.surfaces, values);
    } else {
      for (const auto& s : g.solids) {
        json solid = json::array(), solid_values = json::array();
        for (const auto& shell : s.shells) {
          json shell_values = json::array();
          solid.push_back(shell_json(shell, shell_values));
          solid_values.push_back(std::move(shell_values));
        }
        if (g.type == "Solid") {
          boundaries = std::move(solid);
          values = std::move(solid_values);
        } else {
          boundaries.push_back(std::move(solid));
          values.push_back(std::move(solid_values));
        }
      }
    }
    json out = {{"type", g.type}, {"lod", lod}, {"boundaries", std::move(boundaries)}};
    if (any) out["semantics"] = {{"surfaces", std::move(surfaces)}, {"values", std::move(values)}};
    return out;
  }

  std::string id_;
  GeometryReader geo_;
  std::vector<std::string> notes_;
  AdeTally ade_;
};

}  // namespace

ConvertedBuilding convert_building(const xmlNode* building, const std::string& fallback_id,
                                   const RemoteGeometry* remote) {
  std::string id = gml_id(building);
  if (id.empty()) id = fallback_id;
  return Converter(building, id, remote).run(building);
}

}  // namespace mc::io::citygml
