#include "pipeline/cache.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "config/config.hpp"
#include "io/atomic_file.hpp"
#include "io/cityjson_building.hpp"
#include "io/cityjson_common.hpp"
#include "io/errors.hpp"
#include "output/level_views.hpp"
#include "pipeline/cache_entry.hpp"
#include "pipeline/job.hpp"
#include "io/sha256.hpp"

namespace mc::pipeline {
using namespace mc::report;
using namespace mc::massing;

using nlohmann::json;
namespace fs = std::filesystem;
using SteadyClock = std::chrono::steady_clock;

namespace {

// 2: parts checked and repaired on the output grid (docs/output-format.md); 3: massing analytics;
// 4: a level's result in the report's schema (report/level_json.hpp); 5: masses (docs/massing.md);
// 6: parts of valid solids labelled by exact inside volumes (docs/design.md), masses across layers
// and storeys (docs/massing.md): entries of the same version written before hold other parts;
// 7: slices under a slope join their body's mass; 8: raised low strips beside an upper storey are
// its layers (docs/massing.md)
constexpr int kFormat = 8;

// Settings that do not change a complete result: worker threads, buildings in flight, logging
// (outputs are byte-identical for any thread count). Everything else in the effective config is
// in the key, the deadline included.
json key_config(const Params& p, const RunConfig& rc) {
  return outputs_config_json(effective_config_json(p, rc));
}

// A coordinate as the file stores it: the integer on the transform grid (the reader applied
// scale and translate, so rounding recovers the stored integer exactly), or the real value when
// the file has no transform.
json grid(double v, double scale, double translate, bool present) {
  if (!present) return v;
  return static_cast<int64_t>(std::llround((v - translate) / scale));
}

bool is_morphcut_attribute(const std::string& name) { return name.rfind("morphcut_", 0) == 0; }

json* building_object(mc::io::Feature& f) {
  auto it = f.objects.find(f.id);
  return it != f.objects.end() && it->is_object() ? &*it : nullptr;
}

std::string read_file(const std::string& path, bool& exists) {
  std::ifstream in(path, std::ios::binary);
  exists = static_cast<bool>(in);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw std::runtime_error("read error");
  return s.str();
}

// What run_building added to a feature that had `base` vertices and the building's children
// `children_before` (array or null): the payload of a cache entry.
json delta_of(const BuildingOutcome& out, size_t base, const json& children_before) {
  json payload = {{"outcome", outcome_to_json(out)}};
  const json& b = out.feature.objects.at(out.id);
  json attributes = json::object();
  if (auto a = b.find("attributes"); a != b.end() && a->is_object())
    for (auto it = a->begin(); it != a->end(); ++it)
      if (is_morphcut_attribute(it.key())) attributes[it.key()] = it.value();
  payload["attributes"] = std::move(attributes);
  const json* children = b.contains("children") ? &b["children"] : nullptr;
  payload["children_array"] = children && children->is_array();
  json parts = json::array();
  const size_t kept = children_before.is_array() ? children_before.size() : 0;
  if (children && children->is_array())
    for (size_t i = kept; i < children->size(); ++i) {
      const std::string id = (*children)[i].get<std::string>();
      json objects = {{id, out.feature.objects.at(id)}};
      mc::io::for_each_vertex_ref(objects, [&](json& leaf, const std::string&, const std::string&) {
        const int64_t v = leaf.get<int64_t>();
        if (v < static_cast<int64_t>(base)) throw std::runtime_error("a part refers to an input vertex");
        leaf = v - static_cast<int64_t>(base);
      });
      parts.push_back(json::array({id, std::move(objects[id])}));
    }
  payload["parts"] = std::move(parts);
  json vertices = json::array();
  for (size_t i = base; i < out.feature.vertices.size(); ++i) {
    const Vec3& v = out.feature.vertices[i];
    vertices.push_back(json::array({v.x, v.y, v.z}));
  }
  payload["vertices"] = std::move(vertices);
  return payload;
}

// Rebuilds the outcome from an entry on the (stripped) feature `f`. Everything is checked and
// staged before the feature is touched, so a bad entry leaves `f` as it was.
void apply_entry(const json& payload, mc::io::Feature& f, BuildingOutcome& out) {
  BuildingOutcome staged;
  outcome_from_json(payload.at("outcome"), staged);
  if (staged.status != "ok" && staged.status != "skipped")
    throw std::runtime_error("status " + staged.status);
  std::vector<Vec3> vertices;
  for (const json& v : payload.at("vertices")) {
    if (!v.is_array() || v.size() != 3) throw std::runtime_error("bad vertex");
    vertices.push_back({v[0].get<double>(), v[1].get<double>(), v[2].get<double>()});
  }
  const int64_t base = static_cast<int64_t>(f.vertices.size());
  std::vector<std::pair<std::string, json>> parts;
  for (const json& p : payload.at("parts")) {
    std::string id = p.at(0).get<std::string>();
    if (f.objects.contains(id)) throw std::runtime_error("object id " + id + " already exists");
    json objects = {{id, p.at(1)}};
    if (!objects[id].is_object()) throw std::runtime_error("part " + id + " is not an object");
    mc::io::for_each_vertex_ref(objects, [&](json& leaf, const std::string&, const std::string&) {
      const int64_t v = leaf.get<int64_t>();
      if (v < 0 || v >= static_cast<int64_t>(vertices.size()))
        throw std::runtime_error("vertex index out of range");
      leaf = v + base;
    });
    parts.emplace_back(std::move(id), std::move(objects.begin().value()));
  }
  const json& attributes = payload.at("attributes");
  if (!attributes.is_object()) throw std::runtime_error("attributes are not an object");
  for (auto it = attributes.begin(); it != attributes.end(); ++it)
    if (!is_morphcut_attribute(it.key())) throw std::runtime_error("foreign attribute " + it.key());
  const bool children_array = payload.at("children_array").get<bool>();
  json* b = building_object(f);
  if (!b) throw std::runtime_error("the feature has no building object");

  // Commit (nothing below throws on these checked values).
  f.vertices.insert(f.vertices.end(), vertices.begin(), vertices.end());
  if (children_array && (!b->contains("children") || !(*b)["children"].is_array()))
    (*b)["children"] = json::array();
  for (auto& [id, obj] : parts) {
    (*b)["children"].push_back(id);
    f.objects[id] = std::move(obj);
  }
  if (!attributes.empty()) {
    if (!b->contains("attributes") || !(*b)["attributes"].is_object()) (*b)["attributes"] = json::object();
    for (auto it = attributes.begin(); it != attributes.end(); ++it)
      (*b)["attributes"][it.key()] = it.value();
  }
  out.status = std::move(staged.status);
  out.reason = std::move(staged.reason);
  out.lod = std::move(staged.lod);
  out.size = staged.size;
  out.levels = std::move(staged.levels);
  out.measures = std::move(staged.measures);
  out.massing = std::move(staged.massing);            // massing analytics (massing/massing.hpp)
  out.volume_check = std::move(staged.volume_check);  // the cell's volume check (docs/algorithm.md §6.5)
  out.hausdorff = staged.hausdorff;
  out.problems = std::move(staged.problems);
}

}  // namespace

BuildingCache::BuildingCache(std::string dir, const mc::io::Header& h, const Params& p, const RunConfig& rc)
    : dir_(std::move(dir)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec || !fs::is_directory(dir_)) throw mc::io::WriteError(dir_ + ": cannot create the cache directory");
  json header_facts = {{"version", h.version}};
  for (const char* k : {"transform", "geometry-templates"})
    if (h.root.contains(k)) header_facts[k] = h.root[k];
  // Degrees or feet are decomposed in another frame than the same numbers in metres.
  if (!h.coords.metric()) header_facts["coordinates"] = h.coords.describe();
  context_ = "morphcut-city cache " + std::to_string(kFormat) + "\n" MC_VERSION "\n" +
             key_config(p, rc).dump() + "\n" + header_facts.dump() + "\n";
  transform_ = mc::io::parse_transform(h.root, "header");
}

std::string BuildingCache::key_of(const mc::io::Feature& f) const {
  const mc::io::Transform& t = transform_;
  json canon = json::array();
  for (auto it = f.objects.begin(); it != f.objects.end(); ++it) {
    const json& obj = it.value();
    json entry = {{"id", it.key()}};
    for (const char* k : {"type", "parents", "children", "geometry"})
      if (obj.is_object() && obj.contains(k)) entry[k] = obj[k];
    json wrapper = {{it.key(), std::move(entry)}};
    mc::io::for_each_vertex_ref(wrapper, [&](json& leaf, const std::string&, const std::string&) {
      if (!leaf.is_number_integer() || leaf.get<int64_t>() < 0 || leaf.get<uint64_t>() >= f.vertices.size()) {
        leaf = nullptr;  // a bad reference stays visible in the key
        return;
      }
      const Vec3& v = f.vertices[leaf.get<size_t>()];
      leaf = json::array({grid(v.x, t.scale.x, t.translate.x, t.present),
                          grid(v.y, t.scale.y, t.translate.y, t.present),
                          grid(v.z, t.scale.z, t.translate.z, t.present)});
    });
    canon.push_back(std::move(wrapper.begin().value()));
  }
  mc::io::Sha256 sha;
  sha.update(context_.data(), context_.size());
  const std::string text = canon.dump();
  sha.update(text.data(), text.size());
  return sha.hex();
}

std::string BuildingCache::entry_path(const std::string& key) const {
  return (fs::path(dir_) / key.substr(0, 2) / (key + ".json")).string();
}

BuildingOutcome BuildingCache::run(mc::io::Feature&& f, const mc::io::Header& h, const Params& p,
                                   const RunConfig& rc) {
  if (!mc::io::is_building(f)) return run_building(std::move(f), h, p, rc);
  const auto start = SteadyClock::now();
  mc::output::strip_previous_parts(f);  // the key and the entry are about the input, not an earlier output
  const std::string key = key_of(f);
  const std::string path = entry_path(key);

  try {
    bool exists = false;
    const std::string text = read_file(path, exists);
    if (exists) {
      const size_t nl = text.find('\n');
      if (nl == std::string::npos) throw std::runtime_error("truncated");
      const json head = json::parse(text.substr(0, nl));
      std::string body = text.substr(nl + 1);
      if (!body.empty() && body.back() == '\n') body.pop_back();
      if (head.at("format").get<int>() != kFormat) throw std::runtime_error("unknown format");
      if (head.at("key").get<std::string>() != key)
        throw std::runtime_error("key does not match the file name");
      if (head.at("sha256").get<std::string>() != mc::io::sha256_hex(body))
        throw std::runtime_error("checksum mismatch");
      BuildingOutcome out;
      out.id = f.id;
      out.is_building = true;
      apply_entry(json::parse(body), f, out);
      out.feature = std::move(f);
      out.time.job = std::chrono::duration<double>(SteadyClock::now() - start).count();
      ++hits_;
      return out;
    }
  } catch (const std::exception& e) {
    ++corrupt_;
    std::fprintf(stderr, "morphcut-city: cache: ignoring entry %s (%s); recomputing %s\n", path.c_str(),
                 e.what(), f.id.c_str());
  }

  ++misses_;
  const size_t base = f.vertices.size();
  json children_before = nullptr;
  if (const json* b = building_object(f); b && b->contains("children")) children_before = (*b)["children"];
  BuildingOutcome out = run_building(std::move(f), h, p, rc);
  if (out.status != "ok" && out.status != "skipped") {
    ++not_stored_;
    return out;
  }
  try {
    const std::string body = delta_of(out, base, children_before).dump();
    const json head = {{"format", kFormat}, {"key", key}, {"sha256", mc::io::sha256_hex(body)}};
    fs::create_directories(fs::path(path).parent_path());
    mc::io::AtomicFile file(path);
    file.stream() << head.dump() << '\n' << body << '\n';
    file.commit();
    ++stored_;
  } catch (const std::exception& e) {
    // A cache that cannot be written costs speed, never the result.
    if (store_errors_++ == 0)
      std::fprintf(stderr, "morphcut-city: cache: cannot store %s (%s)\n", path.c_str(), e.what());
  }
  return out;
}

CacheStats BuildingCache::stats() const {
  CacheStats s;
  s.hits = hits_;
  s.misses = misses_;
  s.stored = stored_;
  s.not_stored = not_stored_;
  s.corrupt = corrupt_;
  s.store_errors = store_errors_;
  return s;
}

}  // namespace mc::pipeline
