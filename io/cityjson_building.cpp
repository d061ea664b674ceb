#include "io/cityjson_building.hpp"

#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <limits>
#include <tuple>
#include <map>
#include <set>
#include <unordered_map>

#include "io/cityjson_common.hpp"

namespace mc::io {

namespace {

using nlohmann::json;

const std::set<std::string> kSurfaceTypes = {"MultiSurface", "CompositeSurface", "Solid", "MultiSolid",
                                             "CompositeSolid"};
const std::set<std::string> kOtherKnownTypes = {"MultiPoint", "MultiLineString"};

// One geometry of the building that can contribute faces.
struct Candidate {
  std::string object_id;
  size_t index = 0;                // position in the object's "geometry" array
  const json* geom = nullptr;      // the geometry, or the template for a GeometryInstance
  const json* instance = nullptr;  // the GeometryInstance itself, if any
  std::string type, lod;
};

double lod_value(const std::string& lod) {
  char* end = nullptr;
  const double v = std::strtod(lod.c_str(), &end);
  return (end && *end == '\0' && !lod.empty()) ? v : -std::numeric_limits<double>::infinity();
}

// Building + BuildingPart descendants (through "children"), each once.
std::vector<std::string> building_objects(const Feature& f) {
  std::vector<std::string> out{f.id};
  std::set<std::string> seen{f.id};
  for (size_t i = 0; i < out.size(); ++i) {
    auto obj = f.objects.find(out[i]);
    if (obj == f.objects.end() || !obj->is_object()) continue;
    auto ch = obj->find("children");
    if (ch == obj->end() || !ch->is_array()) continue;
    for (const auto& c : *ch) {
      if (!c.is_string()) continue;
      auto child = f.objects.find(c.get<std::string>());
      if (child == f.objects.end() || !child->is_object()) continue;
      if (child->value("type", "") != "BuildingPart") continue;
      if (seen.insert(c.get<std::string>()).second) out.push_back(c.get<std::string>());
    }
  }
  return out;
}

std::vector<Candidate> candidates(const Feature& f, const Header& h, ProblemLog* log) {
  std::vector<Candidate> out;
  const json* templates = nullptr;
  if (auto gt = h.root.find("geometry-templates"); gt != h.root.end() && gt->is_object())
    if (auto t = gt->find("templates"); t != gt->end() && t->is_array()) templates = &*t;
  for (const auto& id : building_objects(f)) {
    auto obj = f.objects.find(id);
    if (obj == f.objects.end() || !obj->is_object()) continue;
    auto geoms = obj->find("geometry");
    if (geoms == obj->end()) continue;
    if (!geoms->is_array()) {
      if (log) log->add(id + ": \"geometry\" is not an array; skipped");
      continue;
    }
    for (size_t g = 0; g < geoms->size(); ++g) {
      const json& geom = (*geoms)[g];
      Candidate c{id, g, &geom, nullptr, "", ""};
      const std::string where = id + ": geometry #" + std::to_string(g);
      if (!geom.is_object() || !geom.contains("type") || !geom["type"].is_string()) {
        if (log) log->add(where + ": not an object with a string \"type\"; skipped");
        continue;
      }
      c.type = geom["type"].get<std::string>();
      if (c.type == "GeometryInstance") {
        auto t = geom.find("template");
        if (!templates || t == geom.end() || !t->is_number_unsigned() ||
            t->get<size_t>() >= templates->size()) {
          if (log) log->add(where + ": GeometryInstance refers to a missing geometry template; skipped");
          continue;
        }
        c.instance = &geom;
        c.geom = &(*templates)[t->get<size_t>()];
        c.type = c.geom->value("type", "");
      }
      c.lod = lod_string(c.geom->value("lod", json()));
      if (kSurfaceTypes.count(c.type)) {
        out.push_back(std::move(c));
      } else if (!kOtherKnownTypes.count(c.type) && log) {
        log->add(where + ": unknown geometry type \"" + c.type + "\"; skipped");
      }
    }
  }
  return out;
}

// Turns the selected geometries into one PolygonMesh, validating every ring.
class Assembler {
 public:
  Assembler(const Feature& f, const Header& h, BuildingInput& out, ProblemLog& log)
      : f_(f), h_(h), out_(out), log_(log), feature_map_(f.vertices.size(), -1) {}

  void add(const Candidate& c) {
    ctx_ = c.object_id + ": geometry #" + std::to_string(c.index) + " (" + c.type + ", LoD " + c.lod + ")";
    cand_ = &c;
    instance_map_.clear();
    if (c.instance && !prepare_instance(*c.instance)) return;
    const json& b = c.geom->contains("boundaries") ? (*c.geom)["boundaries"] : json();
    const json* values = nullptr;
    labels_ = nullptr;
    if (auto s = c.geom->find("semantics"); s != c.geom->end() && s->is_object()) {
      if (auto v = s->find("values"); v != s->end()) values = &*v;
      if (auto sf = s->find("surfaces"); sf != s->end() && sf->is_array()) labels_ = &*sf;
    }
    // Nesting above the surface level: MultiSurface 0, Solid 1 (shells), Multi/CompositeSolid 2.
    const int levels = (c.type == "Solid")                                      ? 1
                       : (c.type == "MultiSolid" || c.type == "CompositeSolid") ? 2
                                                                                : 0;
    walk(b, values, levels, "");
  }

 private:
  void walk(const json& node, const json* values, int levels, const std::string& path) {
    if (!node.is_array()) {
      log_.add(ctx_ + (path.empty() ? "" : " " + path) +
               ": malformed boundaries (expected an array); skipped");
      return;
    }
    static const char* names[] = {"surface", "shell", "solid"};
    for (size_t i = 0; i < node.size(); ++i) {
      const json* v = (values && values->is_array() && i < values->size()) ? &(*values)[i] : nullptr;
      const std::string p = (path.empty() ? "" : path + " ") + names[levels] + " " + std::to_string(i);
      if (levels > 0) walk(node[i], v, levels - 1, p);
      else add_face(node[i], v, p);
    }
  }

  void add_face(const json& surface, const json* value, const std::string& path) {
    const std::string where = ctx_ + " " + path;
    if (!surface.is_array() || surface.empty()) {
      log_.add(where + ": surface is not a non-empty array of rings; face skipped");
      return;
    }
    mc::Polygon poly;
    for (size_t r = 0; r < surface.size(); ++r) {
      std::string why;
      std::vector<uint32_t> ring = make_ring(surface[r], why);
      if (!why.empty()) {
        if (r == 0) {
          log_.add(where + ": outer ring " + why + "; face skipped");
          return;
        }
        log_.add(where + ": hole " + std::to_string(r) + " " + why + "; hole skipped");
        continue;
      }
      poly.rings.push_back(std::move(ring));
    }
    // A semantic index: parsed files hold unsigned numbers, a feature built in code may hold a
    // signed one (nlohmann::json stores an int as signed).
    if (value && value->is_number_integer() && value->get<int64_t>() >= 0 && labels_ &&
        value->get<size_t>() < labels_->size()) {
      const json& s = (*labels_)[value->get<size_t>()];
      if (s.is_object() && s.contains("type") && s["type"].is_string())
        poly.semantic = out_.mesh.label_index(s["type"].get<std::string>());
    }
    out_.mesh.faces.push_back(std::move(poly));
  }

  // Returns the ring as mesh indices, or sets `why`.
  std::vector<uint32_t> make_ring(const json& ring, std::string& why) {
    std::vector<uint32_t> out;
    if (!ring.is_array()) {
      why = "is not an array of vertex indices";
      return {};
    }
    for (const auto& e : ring) {
      int64_t idx = -1;
      if (e.is_number_integer()) idx = e.get<int64_t>();
      mc::Vec3 p;
      int64_t key;
      if (!resolve(idx, p, key)) {
        why = idx < 0 ? "refers to a vertex that could not be read (" + e.dump() + ")"
                      : "has vertex index " + std::to_string(idx) + " out of range";
        return {};
      }
      if (!mc::is_finite(p)) {
        why = "has a vertex with non-finite coordinates (NaN or inf)";
        return {};
      }
      const uint32_t m = mesh_index(key, p);
      if (out.empty() || out_.mesh.vertices[out.back()] != p) out.push_back(m);
    }
    while (out.size() > 1 && out_.mesh.vertices[out.back()] == out_.mesh.vertices[out.front()])
      out.pop_back();
    std::set<std::tuple<double, double, double>> distinct;
    for (uint32_t m : out)
      distinct.emplace(out_.mesh.vertices[m].x, out_.mesh.vertices[m].y, out_.mesh.vertices[m].z);
    if (distinct.size() < 3) {
      why = "has fewer than 3 distinct points (degenerate)";
      return {};
    }
    return out;
  }

  // Vertex `idx` of the current geometry: a feature vertex, or a transformed template vertex.
  bool resolve(int64_t idx, mc::Vec3& p, int64_t& key) {
    if (idx < 0) return false;
    if (!cand_->instance) {
      if (static_cast<size_t>(idx) >= f_.vertices.size()) return false;
      p = f_.vertices[idx];
      key = idx;
      return true;
    }
    if (static_cast<size_t>(idx) >= template_vertices_->size()) return false;
    const json& v = (*template_vertices_)[idx];
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number()) {
      p = mc::Vec3(NAN, NAN, NAN);
    } else {
      const double x = v[0].get<double>(), y = v[1].get<double>(), z = v[2].get<double>();
      const double* m = matrix_;
      p = mc::Vec3(m[0] * x + m[1] * y + m[2] * z + m[3], m[4] * x + m[5] * y + m[6] * z + m[7],
                   m[8] * x + m[9] * y + m[10] * z + m[11]) +
          reference_;
    }
    key = -1 - idx;  // instance vertices never share with feature vertices
    return true;
  }

  uint32_t mesh_index(int64_t key, const mc::Vec3& p) {
    if (key >= 0) {
      int64_t& slot = feature_map_[key];
      if (slot < 0) {
        slot = static_cast<int64_t>(out_.mesh.vertices.size());
        out_.mesh.vertices.push_back(p);
      }
      return static_cast<uint32_t>(slot);
    }
    auto [it, fresh] = instance_map_.emplace(key, static_cast<uint32_t>(out_.mesh.vertices.size()));
    if (fresh) out_.mesh.vertices.push_back(p);
    return it->second;
  }

  bool prepare_instance(const json& inst) {
    const json* gt = h_.root.contains("geometry-templates") ? &h_.root["geometry-templates"] : nullptr;
    template_vertices_ = (gt && gt->contains("vertices-templates") && (*gt)["vertices-templates"].is_array())
                             ? &(*gt)["vertices-templates"]
                             : nullptr;
    auto b = inst.find("boundaries");
    auto m = inst.find("transformationMatrix");
    const bool ok_ref = b != inst.end() && b->is_array() && b->size() == 1 && (*b)[0].is_number_integer() &&
                        (*b)[0].get<int64_t>() >= 0 && (*b)[0].get<size_t>() < f_.vertices.size();
    bool ok_m = m != inst.end() && m->is_array() && m->size() == 16;
    for (size_t i = 0; ok_m && i < 16; ++i) {
      ok_m = (*m)[i].is_number();
      if (ok_m) matrix_[i] = (*m)[i].get<double>();
    }
    if (!template_vertices_ || !ok_ref || !ok_m) {
      log_.add(ctx_ +
               ": GeometryInstance needs a reference point, a 16-number transformationMatrix and "
               "vertices-templates; skipped");
      return false;
    }
    reference_ = f_.vertices[(*b)[0].get<size_t>()];
    return true;
  }

  const Feature& f_;
  const Header& h_;
  BuildingInput& out_;
  ProblemLog& log_;
  std::vector<int64_t> feature_map_;
  std::unordered_map<int64_t, uint32_t> instance_map_;
  const Candidate* cand_ = nullptr;
  const json* labels_ = nullptr;
  const json* template_vertices_ = nullptr;
  double matrix_[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  mc::Vec3 reference_;
  std::string ctx_;
};

}  // namespace

bool is_building(const Feature& f) {
  auto obj = f.objects.find(f.id);
  return obj != f.objects.end() && obj->is_object() && obj->value("type", "") == "Building";
}

std::vector<std::string> building_lods(const Feature& f, const Header& h) {
  std::vector<std::string> out;
  for (const auto& c : candidates(f, h, nullptr))
    if (std::find(out.begin(), out.end(), c.lod) == out.end()) out.push_back(c.lod);
  return out;
}

BuildingInput extract_building(const Feature& f, const Header& h, const std::string& lod) {
  BuildingInput out;
  out.id = f.id;
  out.problems = f.problems;
  ProblemLog log(out.problems);
  const auto all = candidates(f, h, &log);
  std::string chosen = lod;
  if (lod == "highest") {
    chosen.clear();
    double best = -std::numeric_limits<double>::infinity();
    for (const auto& c : all)
      if (chosen.empty() || lod_value(c.lod) > best) {
        best = lod_value(c.lod);
        chosen = c.lod;
      }
  }
  std::vector<std::string> available;
  Assembler assembler(f, h, out, log);
  for (const auto& c : all) {
    // "highest" takes every geometry numerically equal to the best ("2" and "2.0" alike);
    // an explicit LoD is matched exactly, as the file writes it.
    const bool take =
        lod == "highest"
            ? (c.lod == chosen || (lod_value(c.lod) == lod_value(chosen) && std::isfinite(lod_value(chosen))))
            : c.lod == chosen;
    if (!take) {
      if (std::find(available.begin(), available.end(), c.lod) == available.end()) available.push_back(c.lod);
      continue;
    }
    assembler.add(c);
  }
  if (all.empty()) {
    log.add(f.id + ": building has no surface geometry");
    chosen.clear();
  } else if (out.mesh.faces.empty()) {
    std::string list;
    for (const auto& a : available) list += (list.empty() ? "" : ", ") + a;
    log.add(f.id + ": no usable faces at LoD " + chosen + (list.empty() ? "" : " (available: " + list + ")"));
  }
  out.lod = chosen;
  return out;
}

size_t remove_geometries_at_lod(Feature& f, const Header& h, const std::string& lod) {
  if (lod.empty()) return 0;
  std::map<std::string, std::vector<size_t>> doomed;  // object -> geometry indices
  for (const auto& c : candidates(f, h, nullptr)) {
    const bool same = c.lod == lod || (lod_value(c.lod) == lod_value(lod) && std::isfinite(lod_value(lod)));
    if (!same) continue;
    const json& obj = f.objects[c.object_id];
    const auto a = obj.find("attributes");
    if (a != obj.end() && a->is_object() && a->contains("morphcut_level")) continue;
    doomed[c.object_id].push_back(c.index);
  }
  size_t removed = 0;
  for (auto& [id, indices] : doomed) {
    json& geoms = f.objects[id]["geometry"];
    std::sort(indices.rbegin(), indices.rend());
    for (size_t i : indices) {
      geoms.erase(i);
      ++removed;
    }
  }
  return removed;
}

}  // namespace mc::io
