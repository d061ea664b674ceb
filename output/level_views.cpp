#include "output/level_views.hpp"

#include "massing/massing.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "io/cityjson_building.hpp"
#include "io/cityjson_common.hpp"

namespace mc::output {

using nlohmann::json;

namespace {

double part_level(const json& object) { return object["attributes"]["morphcut_level"].get<double>(); }

// The feature with only the parts `keep` accepts (the others and their ids in "children" left
// out), copying each kept object once; vertices are the feature's until compacted.
template <class Keep>
mc::io::Feature with_parts(const mc::io::Feature& f, Keep keep) {
  mc::io::Feature v;
  v.id = f.id;
  v.problems = f.problems;
  v.extra = f.extra;
  v.vertices = f.vertices;
  v.objects = json::object();
  std::vector<std::string> gone;
  for (auto it = f.objects.begin(); it != f.objects.end(); ++it) {
    if (is_morphcut_part(*it) && !keep(*it)) gone.push_back(it.key());
    else v.objects[it.key()] = *it;
  }
  if (gone.empty()) return v;
  std::sort(gone.begin(), gone.end());
  for (auto& obj : v.objects) {
    if (!obj.is_object()) continue;
    auto ch = obj.find("children");
    if (ch == obj.end() || !ch->is_array()) continue;
    json kept = json::array();
    for (auto& c : *ch)
      if (!c.is_string() || !std::binary_search(gone.begin(), gone.end(), c.get<std::string>()))
        kept.push_back(std::move(c));
    *ch = std::move(kept);
  }
  return v;
}

}  // namespace

std::string level_output_path(const std::string& output, double threshold) {
  std::string base = output, ext;
  for (const char* e : {".city.jsonl", ".city.json", ".jsonl", ".json"})
    if (output.ends_with(e)) {
      ext = e;
      base = output.substr(0, output.size() - ext.size());
      break;
    }
  if (ext.empty()) ext = ".city.json";
  char t[32];
  std::snprintf(t, sizeof t, "%g", threshold);
  return base + ".level-" + t + ext;
}

bool is_morphcut_part(const json& object) {
  if (!object.is_object() || object.value("type", "") != "BuildingPart") return false;
  const auto a = object.find("attributes");
  return a != object.end() && a->is_object() && a->contains("morphcut_level") &&
         (*a)["morphcut_level"].is_number();
}

void compact_vertices(mc::io::Feature& f) {
  std::vector<int64_t> remap(f.vertices.size(), -1);
  mc::io::for_each_vertex_ref(f.objects, [&](json& leaf, const std::string&, const std::string&) {
    if (leaf.is_number_integer() && leaf.get<int64_t>() >= 0 && leaf.get<uint64_t>() < remap.size())
      remap[leaf.get<size_t>()] = 0;
  });
  std::vector<Vec3> kept;
  for (size_t i = 0; i < remap.size(); ++i)
    if (remap[i] == 0) {
      remap[i] = static_cast<int64_t>(kept.size());
      kept.push_back(f.vertices[i]);
    }
  if (kept.size() == f.vertices.size()) return;
  mc::io::for_each_vertex_ref(f.objects, [&](json& leaf, const std::string&, const std::string&) {
    if (leaf.is_number_integer() && leaf.get<int64_t>() >= 0 && leaf.get<uint64_t>() < remap.size())
      leaf = remap[leaf.get<size_t>()];
  });
  f.vertices = std::move(kept);
}

mc::io::Feature annotated_view(const mc::io::Feature& f) {
  mc::io::Feature v = with_parts(f, [](const json&) { return false; });
  compact_vertices(v);
  return v;
}

mc::io::Feature level_view(const mc::io::Feature& f, const mc::io::Header& h, double threshold,
                           const std::string& lod) {
  bool has_parts = false;
  mc::io::Feature v = with_parts(f, [&](const json& part) {
    const bool here = part_level(part) == threshold;
    has_parts = has_parts || here;
    return here;
  });
  if (has_parts) {
    mc::io::remove_geometries_at_lod(v, h, lod);
    auto b = v.objects.find(v.id);
    if (b != v.objects.end() && b->is_object()) {
      if (!b->contains("attributes") || !(*b)["attributes"].is_object()) (*b)["attributes"] = json::object();
      (*b)["attributes"]["morphcut_level"] = threshold;
    }
  }
  compact_vertices(v);
  return v;
}

size_t strip_previous_parts(mc::io::Feature& f) {
  auto b = f.objects.find(f.id);
  if (b == f.objects.end() || !b->is_object()) return 0;
  size_t removed = 0;
  if (auto ch = b->find("children"); ch != b->end() && ch->is_array()) {
    json kept = json::array();
    for (const auto& c : *ch) {
      auto obj = c.is_string() ? f.objects.find(c.get<std::string>()) : f.objects.end();
      const bool ours = obj != f.objects.end() && is_morphcut_part(*obj);
      if (ours) {
        f.objects.erase(obj);
        ++removed;
      } else {
        kept.push_back(c);
      }
    }
    *ch = std::move(kept);
  }
  if (auto a = b->find("attributes"); a != b->end() && a->is_object())
    for (const char* k :
         {"morphcut_status", "morphcut_reason", "morphcut_parts", "morphcut_levels", "morphcut_hausdorff",
          "morphcut_cell_volume", "morphcut_level", "morphcut_volume_check"})
      a->erase(k);
  if (auto a = b->find("attributes"); a != b->end() && a->is_object())
    for (const auto& k : mc::massing::building_attribute_names()) a->erase(k);
  if (removed) compact_vertices(f);
  return removed;
}

}  // namespace mc::output
