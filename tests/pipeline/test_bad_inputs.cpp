// The bad-input corpus through the morphcut-city binary: a broken file stops with exit 2 and
// leaves nothing; a broken building gets its own status and precise reason while every other
// building of the file is processed, and every input object is in the output.
#include "pipeline_fixtures.hpp"

namespace mc::test {
namespace {

#define MC_REQUIRE_CLI()              \
  ASSERT_TRUE(fs::exists(cli_path())) \
      << cli_path() << " missing: build the morphcut_city target before these tests"

std::string bad_file(const std::string& name) { return std::string(MC_SOURCE_DIR) + "/tests/io/bad/" + name; }

struct Expected {
  const char* id;
  const char* status;
  const char* reason;   // exact; "" = none
  const char* problem;  // one of the building's problems in the report; "" = none expected
};

struct CliRun {
  ProcessResult process;
  json report, output;
  std::vector<std::vector<std::string>> csv;
};

// Runs the binary on `input` with `config` (YAML text) and reads every output back.
CliRun run_cli(const TempDir& dir, const std::string& input, const std::string& config,
               const std::string& out_ext = ".city.json") {
  std::ofstream(dir / "c.yaml") << config;
  CliRun r;
  r.process = run_command(cli_path() + " " + input + " -q --threads 2 --config " + (dir / "c.yaml") + " -o " +
                          (dir / ("out" + out_ext)) + " --report " + (dir / "report.json") + " --summary " +
                          (dir / "summary.csv"));
  if (fs::exists(dir / "report.json")) r.report = json::parse(slurp(dir / "report.json"));
  if (fs::exists(dir / ("out" + out_ext))) r.output = load_outputs(dir / ("out" + out_ext));
  if (fs::exists(dir / "summary.csv")) r.csv = parse_csv(slurp(dir / "summary.csv"));
  return r;
}

// Statuses and reasons in the report, the output attributes and the CSV agree with `expected`,
// in input order, and every input CityObject is in the output (`input` empty: the input is not
// readable as a whole, and the expected buildings are all of it).
void check_buildings(const CliRun& r, const std::string& input, const std::vector<Expected>& expected) {
  ASSERT_TRUE(r.report.is_object()) << r.process.output;
  ASSERT_EQ(r.report["buildings"].size(), expected.size());
  ASSERT_EQ(r.csv.size(), expected.size() + 1);
  for (size_t i = 0; i < expected.size(); ++i) {
    const Expected& e = expected[i];
    SCOPED_TRACE(e.id);
    const json& b = r.report["buildings"][i];
    EXPECT_EQ(b["id"].get<std::string>(), e.id);
    EXPECT_EQ(b["status"].get<std::string>(), e.status);
    EXPECT_EQ(b.value("reason", ""), e.reason);
    if (*e.problem) {
      bool found = false;
      for (const auto& p : b.value("problems", json::array())) found |= p.get<std::string>() == e.problem;
      EXPECT_TRUE(found) << "problem not reported: " << e.problem
                         << "\nreported: " << b.value("problems", json());
    }
    const json& attrs = r.output["CityObjects"][e.id]["attributes"];
    EXPECT_EQ(attrs["morphcut_status"].get<std::string>(), e.status);
    EXPECT_EQ(attrs.value("morphcut_reason", ""), e.reason);
    EXPECT_EQ(r.csv[i + 1][0], e.id);
    EXPECT_EQ(r.csv[i + 1][1], e.status);
    EXPECT_EQ(r.csv[i + 1][2], e.reason);
    // Only ok and partial buildings get parts.
    size_t parts = 0;
    for (const auto& c : r.output["CityObjects"][e.id].value("children", json::array()))
      parts += c.get<std::string>().find("-mc") != std::string::npos;
    EXPECT_EQ(parts > 0, std::string(e.status) == "ok" || std::string(e.status) == "partial");
  }
  if (input.empty()) return;
  const json in = load_city(input);
  for (auto it = in["CityObjects"].begin(); it != in["CityObjects"].end(); ++it)
    EXPECT_TRUE(r.output["CityObjects"].contains(it.key())) << it.key() << " lost";
}

const char* kQuick = "decompose:\n  levels: [0.1, 0.01]\n";

// One defect per building (tests/io/bad/mixed_buildings.city.json), good buildings first and
// last. Repairable defects (open, inverted, duplicated, degenerate faces) still give "ok".
TEST(BadInputs, EachBrokenBuildingGetsItsStatusAndTheRestIsProcessed) {
  MC_REQUIRE_CLI();
  TempDir dir("bad_mixed");
  const std::string input = bad_file("mixed_buildings.city.json");
  const CliRun r = run_cli(dir, input, kQuick);
  EXPECT_EQ(r.process.exit_code, 1) << r.process.output;  // one building failed
  check_buildings(
      r, input,
      {{"good_first", "ok", "", ""},
       {"open_shell", "ok", "", ""},
       {"inverted_shell", "ok", "", ""},
       {"duplicate_vertices", "ok", "", "16 duplicate vertices merged"},
       {"zero_area_faces", "ok", "",
        "zero_area_faces: geometry #0 (MultiSurface, LoD 2.2) surface 7: outer ring has fewer than 3 "
        "distinct points "
        "(degenerate); face skipped"},
       {"nested_multisolid", "skipped",
        "no surface geometry; nested_multisolid: geometry #0 (MultiSolid, LoD 2.2) solid 0 shell 0 surface "
        "0: outer "
        "ring refers to a vertex that could not be read ([0,3,2,1]); face skipped",
        "nested_multisolid: no usable faces at LoD 2.2"},
       {"index_out_of_range", "skipped",
        "no surface geometry; index_out_of_range: geometry #0: vertex index 99999 out of range (108 "
        "vertices)",
        "index_out_of_range: geometry #0: vertex index 99998 out of range (108 vertices)"},
       {"non_finite_vertex", "skipped",
        "no surface geometry; non_finite_vertex: geometry #0: uses a vertex with non-finite coordinates (NaN "
        "or inf)",
        ""},
       {"wrong_types", "skipped",
        "no surface geometry; wrong_types: geometry #0: \"abc\" is not a vertex index",
        "wrong_types: geometry #0 (Solid, LoD 2.2): malformed boundaries (expected an array); skipped"},
       {"flat", "failed", "no interior: the oracle found no inside cell", ""},
       {"no_geometry", "skipped", "no surface geometry; no_geometry: building has no surface geometry", ""},
       {"good_last", "ok", "", ""}});
  EXPECT_EQ(r.report["counts"], json({{"ok", 6}, {"partial", 0}, {"failed", 1}, {"skipped", 5}}));
}

// Vertices far from the origin in a 1.0 file without "transform" (float coordinates): up to
// 1e15 the 10 m cubes are decomposed; at 1e300 the cube collapses in double precision, and the
// building fails with the collapsed faces listed.
TEST(BadInputs, HugeCoordinatesWithoutTransform) {
  MC_REQUIRE_CLI();
  TempDir dir("bad_huge_coords");
  json objects = json::object(), vertices = json::array();
  const std::vector<std::pair<std::string, std::array<double, 2>>> at = {{"near", {85000.5, 446000.25}},
                                                                         {"far_1e9", {1e9, 1e9}},
                                                                         {"far_1e15", {1e15, -1e15}},
                                                                         {"far_1e300", {1e300, 0}}};
  for (const auto& [id, xy] : at) {
    const size_t b = vertices.size();
    for (int k = 0; k < 8; ++k)
      vertices.push_back({xy[0] + 10.0 * ((k == 1 || k == 2 || k == 5 || k == 6) ? 1 : 0),
                          xy[1] + 10.0 * ((k == 2 || k == 3 || k == 6 || k == 7) ? 1 : 0), 10.0 * (k >= 4)});
    json shell = json::array();
    for (const auto& f : std::vector<std::vector<int>>{
             {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}) {
      json ring = json::array();
      for (int v : f) ring.push_back(b + v);
      shell.push_back(json::array({ring}));
    }
    objects[id] = {
        {"type", "Building"},
        {"geometry", json::array({{{"type", "Solid"}, {"lod", 2}, {"boundaries", json::array({shell})}}})}};
  }
  const std::string input = dir / "huge.city.json";
  std::ofstream(input)
      << json({{"type", "CityJSON"}, {"version", "1.0"}, {"CityObjects", objects}, {"vertices", vertices}})
             .dump();
  const CliRun r = run_cli(dir, input, kQuick);
  EXPECT_EQ(r.process.exit_code, 1) << r.process.output;
  // nlohmann's objects are sorted by key, so is the file.
  check_buildings(
      r, input,
      {{"far_1e15", "ok", "", ""},
       {"far_1e300", "failed", "no interior: the oracle found no inside cell",
        "far_1e300: geometry #0 (Solid, LoD 2) shell 0 surface 0: outer ring has fewer than 3 distinct "
        "points (degenerate); face skipped"},
       {"far_1e9", "ok", "", ""},
       {"near", "ok", "", ""}});
  // The parts of the far buildings are where the input is (no transform: written as floats).
  const json& v = r.output["vertices"];
  bool near_1e15 = false;
  for (const auto& p : v)
    near_1e15 |= std::abs(p[0].get<double>() - 1e15) < 20 && std::abs(p[1].get<double>() + 1e15) < 20;
  EXPECT_TRUE(near_1e15);
}

// A 100 000-face building (a finely triangulated roof) between two good ones: skipped by the
// max_faces guard in well under a second instead of holding a worker for its whole deadline.
TEST(BadInputs, HugeBuildingIsSkippedAsTooLarge) {
  MC_REQUIRE_CLI();
  TempDir dir("bad_big");
  const int n = 224;  // 2 n^2 = 100 352 roof triangles, + floor + 4 walls
  json v = json::array(), faces = json::array();
  auto idx = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) v.push_back({i, j, 1000});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      faces.push_back(json::array({json::array({idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)})}));
      faces.push_back(json::array({json::array({idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)})}));
    }
  const int base = static_cast<int>(v.size());
  for (auto [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {n, 0}, {n, n}, {0, n}}) v.push_back({x, y, 0});
  faces.push_back(json::array({json::array({base, base + 3, base + 2, base + 1})}));
  const std::vector<std::vector<int>> sides = {
      {idx(0, 0), idx(n, 0)}, {idx(n, 0), idx(n, n)}, {idx(n, n), idx(0, n)}, {idx(0, n), idx(0, 0)}};
  for (int k = 0; k < 4; ++k) {  // each wall: two floor corners and the roof edge above them
    json ring = json::array({base + k, base + (k + 1) % 4});
    const int a = sides[k][0], b = sides[k][1], step = (b - a) / n;
    for (int s = n; s >= 0; --s) ring.push_back(a + s * step);
    faces.push_back(json::array({ring}));
  }
  auto cube = [&](int x0) {
    const json shell = mc::test::append_cube_shell(v, x0, 1000);
    return json::array({{{"type", "Solid"}, {"lod", "2.2"}, {"boundaries", json::array({shell})}}});
  };
  json objects = {
      {"before", {{"type", "Building"}, {"geometry", cube(-5000)}}},
      {"huge_mesh",
       {{"type", "Building"},
        {"geometry", json::array({{{"type", "MultiSurface"}, {"lod", "2.2"}, {"boundaries", faces}}})}}},
      {"after", {{"type", "Building"}, {"geometry", cube(50000)}}}};
  const std::string input = dir / "big.city.json";
  std::ofstream(input) << json({{"type", "CityJSON"},
                                {"version", "2.0"},
                                {"transform", {{"scale", {0.01, 0.01, 0.01}}, {"translate", {0, 0, 0}}}},
                                {"CityObjects", objects},
                                {"vertices", v}})
                              .dump();
  const CliRun r = run_cli(dir, input, kQuick);
  EXPECT_EQ(r.process.exit_code, 0) << r.process.output;  // ok and skipped only
  // nlohmann's objects are sorted by key: after, before, huge_mesh.
  check_buildings(r, input,
                  {{"after", "ok", "", ""},
                   {"before", "ok", "", ""},
                   {"huge_mesh", "skipped", "too large: 100357 faces > max_faces (50000)", ""}});
  EXPECT_LT(r.report["buildings"][2]["timings"]["job"].get<double>(), 5.0);
  // The limit is a validated setting (0 = no limit).
  std::ofstream(dir / "neg.yaml") << "max_faces: -1\n";
  const ProcessResult neg = run_command(cli_path() + " " + input + " --config " + (dir / "neg.yaml"));
  EXPECT_EQ(neg.exit_code, 2);
  EXPECT_NE(neg.output.find("max_faces"), std::string::npos) << neg.output;
}

// CityJSONSeq lines that cannot be read are skipped and listed in the report; every readable
// feature is processed and written.
TEST(BadInputs, BrokenSequenceLinesAreSkippedAndReported) {
  MC_REQUIRE_CLI();
  TempDir dir("bad_seq");
  const std::string input = bad_file("bad_features.city.jsonl");
  const CliRun r = run_cli(dir, input, kQuick, ".city.jsonl");
  EXPECT_EQ(r.process.exit_code, 1) << r.process.output;  // the one-triangle building fails
  EXPECT_EQ(r.report["reader_problems"], json::array({input + ": line 6: not a JSON object; line skipped"}));
  check_buildings(
      r, "",
      {{"novertices", "skipped",
        "no surface geometry; novertices: feature line 2 has no \"vertices\" array; its geometry cannot be "
        "read",
        ""},
       {"vertices_wrong_type", "skipped",
        "no surface geometry; vertices_wrong_type: feature line 3 has no \"vertices\" array; its geometry "
        "cannot be "
        "read",
        ""},
       {"noid", "skipped",
        "no surface geometry; noid: feature line 4 has no valid \"id\"; using this top-level object", ""},
       {"other", "skipped",
        "no surface geometry; other: feature line 5 has no valid \"id\"; using this top-level object", ""},
       {"good", "failed", "no interior: the oracle found no inside cell", ""}});
}

// A file that cannot be read as a whole: exit 2, the reason on stderr, and no output at all.
TEST(BadInputs, UnreadableFilesExitTwoAndWriteNothing) {
  MC_REQUIRE_CLI();
  for (const char* name :
       {"empty.city.json", "garbage.city.json", "truncated.city.json", "wrong_version.city.json",
        "missing_vertices.city.json", "vertices_object.city.json", "version_number.city.json",
        "nan_literal.city.json", "invalid_utf8.city.json", "garbage.city.jsonl", "truncated.city.jsonl",
        "empty.city.jsonl"}) {
    SCOPED_TRACE(name);
    TempDir dir("bad_fatal");
    const ProcessResult r =
        run_command("cd " + dir.path.string() + " && " + cli_path() + " " + bad_file(name));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(bad_file(name) + ": "), std::string::npos) << r.output;
    EXPECT_TRUE(fs::is_empty(dir.path));
  }
}

}  // namespace
}  // namespace mc::test
