// Shared helpers of the pipeline tests: where the real data lives, reading outputs back, and an
// independent closedness check of the written Solids.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "config/config.hpp"
#include "output/validate.hpp"

namespace mc::test {

namespace fs = std::filesystem;
using nlohmann::json;

// A file of the shared reference data (../shared/datasets/cityjson/...), or of datasets/.
inline std::string data_file(const std::string& rel) {
  for (const std::string& base : {std::string(MC_SOURCE_DIR) + "/../shared/datasets/cityjson/",
                                  std::string(MC_SOURCE_DIR) + "/datasets/"})
    if (fs::exists(base + rel)) return base + rel;
  return {};
}

#define MC_REQUIRE_DATA(var, rel)                     \
  const std::string var = ::mc::test::data_file(rel); \
  if (var.empty()) GTEST_SKIP() << "test data " << rel << " not found";

// A fresh empty directory under the build tree, removed by the destructor.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name) {
    path = fs::path(MC_BINARY_DIR) / "test_tmp" / (name + "." + std::to_string(::getpid()));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string operator/(const std::string& f) const { return (path / f).string(); }
};

// The defaults a user gets (config/lod.yaml), which are what the CLI runs with; core's Params{}
// are not necessarily the same.
inline mc::LoadedConfig default_config() { return mc::load_config_string(""); }

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A CityJSON file or a CityJSONSeq file as one document: CityObjects merged, vertices of every
// feature appended (indices re-based), so both formats are checked the same way.
inline json load_city(const std::string& path) {
  const std::string text = slurp(path);
  if (path.size() < 6 || path.substr(path.size() - 6) != ".jsonl") return json::parse(text);
  std::istringstream in(text);
  std::string line;
  json doc;
  bool first = true;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    json j = json::parse(line);
    if (first) {
      doc = j;
      first = false;
      continue;
    }
    const int64_t base = static_cast<int64_t>(doc["vertices"].size());
    for (auto& v : j["vertices"]) doc["vertices"].push_back(v);
    for (auto it = j["CityObjects"].begin(); it != j["CityObjects"].end(); ++it) {
      json obj = it.value();
      if (obj.contains("geometry"))
        for (auto& g : obj["geometry"]) {
          std::function<void(json&)> shift = [&](json& n) {
            if (n.is_array())
              for (auto& c : n) shift(c);
            else if (n.is_number_integer()) n = n.get<int64_t>() + base;
          };
          if (g.contains("boundaries")) shift(g["boundaries"]);
        }
      doc["CityObjects"][it.key()] = obj;
    }
  }
  return doc;
}

// The level files a run wrote beside its main output (docs/output-format.md), in level order
// as the file names sort: OUT.city.json -> OUT.level-<t>.city.json.
inline std::vector<std::string> level_files(const std::string& main_output) {
  std::string base = main_output, ext;
  for (const char* e : {".city.jsonl", ".city.json", ".jsonl", ".json"}) {
    const std::string x = e;
    if (main_output.size() > x.size() &&
        main_output.compare(main_output.size() - x.size(), x.size(), x) == 0) {
      ext = x;
      base = main_output.substr(0, main_output.size() - x.size());
      break;
    }
  }
  const fs::path dir = fs::path(base).parent_path().empty() ? fs::path(".") : fs::path(base).parent_path();
  const std::string prefix = fs::path(base).filename().string() + ".level-";
  std::vector<std::string> out;
  if (!fs::exists(dir)) return out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && name.size() > ext.size() &&
        name.compare(name.size() - ext.size(), ext.size(), ext) == 0 &&
        name.find('.', prefix.size()) != std::string::npos)
      out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A run's outputs as one document with every level: the annotated input plus every level file's
// parts (vertices re-based, listed as the Building's children). Checks written for "all parts of
// a building" read this; checks of one file's coherence read the files themselves.
inline json load_outputs(const std::string& main_output) {
  json doc = load_city(main_output);
  for (const auto& lf : level_files(main_output)) {
    const json level = load_city(lf);
    const int64_t base = static_cast<int64_t>(doc["vertices"].size());
    for (const auto& v : level["vertices"]) doc["vertices"].push_back(v);
    for (auto it = level["CityObjects"].begin(); it != level["CityObjects"].end(); ++it) {
      if (!it->contains("attributes") || !(*it)["attributes"].contains("morphcut_level") ||
          (*it)["type"] != "BuildingPart")
        continue;
      json obj = it.value();
      std::function<void(json&)> shift = [&](json& n) {
        if (n.is_array())
          for (auto& c : n) shift(c);
        else if (n.is_number_integer()) n = n.get<int64_t>() + base;
      };
      for (auto& g : obj["geometry"]) shift(g["boundaries"]);
      doc["CityObjects"][it.key()] = obj;
      const std::string parent = obj["parents"][0];
      doc["CityObjects"][parent]["children"].push_back(it.key());
    }
  }
  return doc;
}

// Empty when every edge of the Solid's outer shell is used exactly twice, in opposite
// directions, after merging vertices with equal coordinates.
inline std::string solid_defect(const json& geometry, const json& vertices) {
  if (geometry.value("type", "") != "Solid") return "not a Solid";
  if (geometry["boundaries"].size() != 1) return "expected exactly one shell";
  std::map<std::tuple<double, double, double>, int> ids;
  auto id = [&](int64_t v) {
    const auto& c = vertices.at(static_cast<size_t>(v));
    auto key = std::make_tuple(c[0].get<double>(), c[1].get<double>(), c[2].get<double>());
    return ids.try_emplace(key, static_cast<int>(ids.size())).first->second;
  };
  std::map<std::pair<int, int>, int> edges;
  for (const auto& surface : geometry["boundaries"][0])
    for (const auto& ring : surface) {
      if (ring.size() < 3) return "ring with fewer than 3 vertices";
      for (size_t i = 0; i < ring.size(); ++i) {
        const int a = id(ring[i].get<int64_t>()), b = id(ring[(i + 1) % ring.size()].get<int64_t>());
        if (a == b) return "zero-length edge";
        ++edges[{a, b}];
      }
    }
  for (const auto& [e, n] : edges) {
    if (n != 1) return "edge used " + std::to_string(n) + " times in one direction";
    auto back = edges.find({e.second, e.first});
    if (back == edges.end() || back->second != 1) return "edge without its opposite";
  }
  return {};
}

// `morphcut-city validate` on an output (output/validate.hpp): every part a valid Solid, parts
// of a level not overlapping and adding up to the cell volume, structure sound. Call it on every
// output city a test produces: EXPECT-fails with the invalid objects' errors. `known_defect`: errors
// containing this text are printed instead (an input with a documented, still open core defect;
// every other check keeps failing the test).
// A main output is checked with its level files (each file on its own: every file is a city).
inline void expect_valid_output(const std::string& path, size_t min_parts = 1,
                                const std::string& known_defect = "") {
  std::string errors, known;
  size_t parts = 0;
  std::vector<std::string> files{path};
  for (const auto& lf : level_files(path)) files.push_back(lf);
  for (const auto& file : files) {
    const auto s = mc::output::validate_city(file, {}, [&](const mc::output::ObjectReport& r) {
      for (const auto& e : r.errors) {
        const std::string line =
            r.id + ": " + std::to_string(e.code) + " " + e.name + ": " + e.message + "\n";
        (!known_defect.empty() && line.find(known_defect) != std::string::npos ? known : errors) += line;
      }
    });
    EXPECT_TRUE(s.file_problems.empty())
        << file << ": " << (s.file_problems.empty() ? "" : s.file_problems.front());
    parts += s.counts.parts;
  }
  EXPECT_EQ(errors, "") << path;
  EXPECT_GE(parts, min_parts) << path;
  if (!known.empty()) std::fprintf(stderr, "known defect (not failed): %s", known.c_str());
}

struct ProcessResult {
  int exit_code = -1;
  std::string output;  // stdout + stderr
};

// Runs a shell command line, capturing stdout and stderr.
inline ProcessResult run_command(const std::string& cmd) {
  ProcessResult r;
  FILE* p = ::popen((cmd + " 2>&1").c_str(), "r");
  if (!p) return r;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.output.append(buf, n);
  const int status = ::pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

inline std::string cli_path() { return std::string(MC_BINARY_DIR) + "/tools/morphcut-city"; }

// An axis-aligned cube [x0, x0 + size] x [0, size] x [0, size] appended to `vertices` (CityJSON
// vertex list; T = int for files with a transform): its outward shell of 6 quads indexing them.
template <class T>
json append_cube_shell(json& vertices, T x0, T size) {
  const size_t b = vertices.size();
  for (int k = 0; k < 8; ++k)
    vertices.push_back({x0 + size * T((k == 1 || k == 2 || k == 5 || k == 6) ? 1 : 0),
                        size * T((k == 2 || k == 3 || k == 6 || k == 7) ? 1 : 0), size * T(k >= 4)});
  json shell = json::array();
  for (const auto& f : std::vector<std::vector<int>>{
           {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}) {
    json ring = json::array();
    for (int k : f) ring.push_back(b + k);
    shell.push_back(json::array({ring}));
  }
  return shell;
}

// ajv-cli as tools/setup-deps.sh installs it (build/node_tools), or empty when it is not there.
inline std::string ajv_path() {
  for (const std::string& base : {std::string(MC_SOURCE_DIR) + "/build", std::string(MC_BINARY_DIR)}) {
    const std::string p = base + "/node_tools/node_modules/.bin/ajv";
    if (fs::exists(p)) return p;
  }
  return {};
}

// The official CityJSON 2.0 schemas in ../shared.
inline std::string schema_dir() {
  return std::string(MC_SOURCE_DIR) + "/../shared/datasets/cityjson/schemas/2.0";
}

// CSV rows split into fields (RFC 4180 quoting; CRLF or LF line ends).
inline std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows(1);
  std::string field;
  bool quoted = false, any = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') field += '"', ++i;
      else if (c == '"') quoted = false;
      else field += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().push_back(field), field.clear();
    } else if (c == '\r') {
    } else if (c == '\n') {
      rows.back().push_back(field), field.clear();
      rows.emplace_back();
    } else {
      field += c;
    }
    any = true;
  }
  if (!field.empty() || (!rows.back().empty())) rows.back().push_back(field);
  if (rows.back().empty()) rows.pop_back();
  (void)any;
  return rows;
}

}  // namespace mc::test
