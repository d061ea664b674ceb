// Round trip of every CityJSON file in ../shared/datasets/cityjson through reader and writer:
// same version, same root members, same object ids, and every object (attributes, semantics,
// appearance references, hierarchy) equal once its vertex references are replaced by
// coordinates, which must be identical after re-quantisation. The reference side is loaded with
// a plain DOM here, independently of the streaming reader.
#include <array>
#include <cmath>
#include <set>

#include "io_test_util.hpp"

namespace mc::io::test {
namespace {

using nlohmann::json;

struct Model {
  std::string version;
  json root = json::object();           // root members but CityObjects and vertices
  std::map<std::string, json> objects;  // vertex references replaced by [x, y, z]
  std::map<std::string, json> extras;   // CityJSONSeq feature members besides the standard ones
};

json deref(const json& node, const std::vector<std::array<double, 3>>& v) {
  if (node.is_array()) {
    json out = json::array();
    for (const auto& c : node) out.push_back(deref(c, v));
    return out;
  }
  if (node.is_number_integer() && node.get<int64_t>() >= 0 && node.get<uint64_t>() < v.size()) {
    const auto& p = v[node.get<size_t>()];
    return json::array({p[0], p[1], p[2]});
  }
  return json("bad reference " + node.dump());
}

void deref_objects(const json& objects, const std::vector<std::array<double, 3>>& v, Model& m) {
  for (auto it = objects.begin(); it != objects.end(); ++it) {
    json o = *it;
    if (o.contains("geometry"))
      for (auto& g : o["geometry"])
        if (g.contains("boundaries")) g["boundaries"] = deref(g["boundaries"], v);
    if (o.contains("address"))
      for (auto& a : o["address"])
        if (a.contains("location") && a["location"].contains("boundaries"))
          a["location"]["boundaries"] = deref(a["location"]["boundaries"], v);
    EXPECT_TRUE(m.objects.emplace(it.key(), std::move(o)).second) << "duplicate id " << it.key();
  }
}

std::vector<std::array<double, 3>> real_vertices(const json& verts, const json& root) {
  std::array<double, 3> s{1, 1, 1}, t{0, 0, 0};
  if (root.contains("transform"))
    for (int i = 0; i < 3; ++i) {
      s[i] = root["transform"]["scale"][i].get<double>();
      t[i] = root["transform"]["translate"][i].get<double>();
    }
  std::vector<std::array<double, 3>> out;
  for (const auto& p : verts)
    out.push_back({p[0].get<double>() * s[0] + t[0], p[1].get<double>() * s[1] + t[1],
                   p[2].get<double>() * s[2] + t[2]});
  return out;
}

Model load_model(const std::string& path) {
  Model m;
  std::ifstream in(path, std::ios::binary);
  if (path.size() > 6 && path.substr(path.size() - 6) == ".jsonl") {
    std::string line;
    std::getline(in, line);
    m.root = json::parse(line);
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      json f = json::parse(line);
      deref_objects(f["CityObjects"], real_vertices(f["vertices"], m.root), m);
      json extra = json::object();
      for (auto it = f.begin(); it != f.end(); ++it)
        if (it.key() != "type" && it.key() != "id" && it.key() != "CityObjects" && it.key() != "vertices")
          extra[it.key()] = *it;
      if (!extra.empty()) m.extras[f["id"].get<std::string>()] = extra;
    }
  } else {
    m.root = json::parse(in);
    deref_objects(m.root["CityObjects"], real_vertices(m.root["vertices"], m.root), m);
  }
  m.root.erase("CityObjects");
  m.root.erase("vertices");
  m.version = m.root.value("version", "");
  return m;
}

void expect_same(const Model& a, const Model& b, bool same_format) {
  EXPECT_EQ(a.version, b.version);
  if (same_format) { EXPECT_EQ(a.root, b.root); }
  EXPECT_EQ(a.objects.size(), b.objects.size());
  for (const auto& [id, obj] : a.objects) {
    auto it = b.objects.find(id);
    ASSERT_NE(it, b.objects.end()) << "object " << id << " missing";
    EXPECT_EQ(obj, it->second) << "object " << id << " differs";
  }
  if (same_format) { EXPECT_EQ(a.extras, b.extras); }
}

std::string output_name(const std::string& input) {
  return input.size() > 6 && input.substr(input.size() - 6) == ".jsonl" ? "out.city.jsonl" : "out.city.json";
}

void round_trip(const std::string& in, const std::string& out) {
  CityJsonReader r(in);
  CityJsonWriter w(out, r.header());
  Feature f;
  while (r.next(f)) w.write(f);
  w.close();
}

// Inputs that are not CityJSON at all, with the exact error they must give.
const std::map<std::string, std::string> kNotCityJson = {
    {"cityjson-corpus/v2_0/cityjsonfeature_minimal.city.jsonl",
     ": line 1: not a CityJSONSeq header (a CityJSONSeq starts with one CityJSON object on one line): parse "
     "error at "
     "line 1, column 2: syntax error while parsing object key - unexpected end of input; expected string "
     "literal"}};

TEST(RoundTrip, EveryFileOfTheSharedCorpus) {
  if (!have_shared()) GTEST_SKIP() << "no " << shared_dir() << " (CI has it at ../shared)";
  const fs::path base = fs::path(shared_dir()) / "cityjson";
  std::set<std::string> manifest;
  {
    std::ifstream in(base / "MANIFEST.tsv");
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) manifest.insert(line.substr(0, line.find('\t')));
  }
  ASSERT_GE(manifest.size(), 60u);
  std::set<std::string> seen;
  for (const auto& e : fs::recursive_directory_iterator(base)) {
    const std::string rel = fs::relative(e.path(), base).string();
    const std::string ext = e.path().extension().string();
    if (!e.is_regular_file() || rel.rfind("schemas/", 0) == 0 || (ext != ".json" && ext != ".jsonl"))
      continue;
    seen.insert(rel);
    SCOPED_TRACE(rel);
    const std::string in = e.path().string();
    if (auto bad = kNotCityJson.find(rel); bad != kNotCityJson.end()) {
      EXPECT_EQ(open_error(in), in + bad->second);
      continue;
    }
    ScratchDir dir;
    const std::string out = dir.file(output_name(in));
    ASSERT_NO_THROW(round_trip(in, out));
    expect_same(load_model(in), load_model(out), true);
    // Re-reading our own output gives no problems the input did not have.
    const auto again = read_all(out);
    for (const auto& f : again.features) EXPECT_TRUE(f.problems.empty()) << joined(f.problems);
  }
  EXPECT_EQ(seen, manifest);  // every listed file was visited
}

TEST(RoundTrip, DocumentToSequenceMatchesTheSequenceTwin) {
  ScratchDir dir;
  const std::string seq = dir.file("tile.city.jsonl"), doc = dir.file("tile.city.json");
  round_trip(project_data("3dbag/3dbag_5910.city.json"), seq);
  expect_same(load_model(project_data("3dbag/3dbag_5910.city.jsonl")), load_model(seq), false);
  round_trip(project_data("3dbag/3dbag_5910.city.jsonl"), doc);
  expect_same(load_model(project_data("3dbag/3dbag_5910.city.json")), load_model(doc), false);
  // The header line carries the transform and empty CityObjects/vertices.
  std::ifstream in(seq);
  std::string first;
  std::getline(in, first);
  const json h = json::parse(first);
  EXPECT_EQ(h["type"], "CityJSON");
  EXPECT_EQ(h["version"], "2.0");
  EXPECT_TRUE(h["CityObjects"].empty());
  EXPECT_TRUE(h["vertices"].empty());
  EXPECT_TRUE(h.contains("transform"));
}

TEST(RoundTrip, ProjectDatasetsRoundTrip) {
  for (const char* rel :
       {"3dbag/3dbag_b2.city.json", "3dbag/3dbag_b2.city.jsonl", "3dbag/delft_subset.city.jsonl",
        "edge/dummy_template_void.city.json", "edge/hollow_solid.city.json", "edge/msol_v10.city.json",
        "edge/multi_lod.city.json", "edge/DH_01_subs.v20.city.json"}) {
    SCOPED_TRACE(rel);
    ScratchDir dir;
    const std::string in = project_data(rel), out = dir.file(output_name(in));
    round_trip(in, out);
    expect_same(load_model(in), load_model(out), true);
  }
}

}  // namespace
}  // namespace mc::io::test
