// run_city end to end on real files: nothing lost, closed parts, reports, determinism, failures.
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>

#include "config/config.hpp"
#include "io/cityjson.hpp"
#include "pipeline/run.hpp"
#include "report/summary_csv.hpp"
#include "pipeline_fixtures.hpp"

namespace mc::pipeline {
using namespace mc::massing;
using namespace mc::output;
using namespace mc::report;
namespace {

using mc::test::json;

struct Outputs {
  RunResult result;
  std::string output, report, summary;
};

Outputs run_on(const std::string& input, const mc::test::TempDir& dir, const std::string& tag, int threads,
               Params p = mc::test::default_config().params, RunConfig rc = {},
               std::function<void(mc::io::Feature&)> hook = {}) {
  const bool seq = input.size() > 6 && input.substr(input.size() - 6) == ".jsonl";
  Outputs o;
  o.output = dir / (tag + (seq ? ".city.jsonl" : ".city.json"));
  o.report = dir / (tag + ".report.json");
  o.summary = dir / (tag + ".csv");
  RunOptions opt;
  opt.input = input;
  opt.output = o.output;
  opt.report = o.report;
  opt.summary = o.summary;
  opt.before_job = std::move(hook);
  p.threads = threads;
  o.result = run_city(opt, p, rc);
  return o;
}

// Every input object is in the output, unchanged except for the Buildings' children and
// morphcut attributes; every added object is a closed BuildingPart of a Building.
void check_output(const std::string& input, const std::string& output, const std::string& known_defect = "") {
  const json in = mc::test::load_city(input);
  const json out = mc::test::load_outputs(output);
  EXPECT_EQ(out["version"], in["version"]);
  EXPECT_EQ(out["transform"], in["transform"]);
  EXPECT_EQ(out["metadata"], in["metadata"]);
  for (auto it = in["CityObjects"].begin(); it != in["CityObjects"].end(); ++it) {
    ASSERT_TRUE(out["CityObjects"].contains(it.key())) << it.key() << " lost";
    json o = out["CityObjects"][it.key()];
    if (o["type"] == "Building") {
      // Every attribute morphcut adds to a Building starts with morphcut_ (docs/output-format.md).
      std::vector<std::string> ours;
      for (auto a = o["attributes"].begin(); a != o["attributes"].end(); ++a)
        if (a.key().rfind("morphcut_", 0) == 0) ours.push_back(a.key());
      for (const auto& k : ours) o["attributes"].erase(k);
      if (o["attributes"].empty() && !it.value().contains("attributes")) o.erase("attributes");
      json kept = json::array();
      for (const auto& c : o["children"])
        if (c.get<std::string>().find("-mc") == std::string::npos) kept.push_back(c);
      o["children"] = kept;
      if (kept.empty() && !it.value().contains("children")) o.erase("children");
      EXPECT_TRUE(out["CityObjects"][it.key()]["attributes"].contains("morphcut_status")) << it.key();
    }
    // Geometry boundaries are re-indexed in a .city.json, so compare everything else.
    json a = o, b = it.value();
    a.erase("geometry"), b.erase("geometry");
    EXPECT_EQ(a, b) << it.key();
    EXPECT_EQ(o.contains("geometry"), it.value().contains("geometry"));
  }
  for (auto it = out["CityObjects"].begin(); it != out["CityObjects"].end(); ++it) {
    if (in["CityObjects"].contains(it.key())) continue;
    const json& part = it.value();
    EXPECT_EQ(part["type"], "BuildingPart") << it.key();
    const std::string parent = part["parents"][0];
    EXPECT_EQ(out["CityObjects"][parent]["type"], "Building");
    EXPECT_EQ(mc::test::solid_defect(part["geometry"][0], out["vertices"]), "") << it.key();
  }
  // morphcut-city validate: valid solids that tile each cell.
  mc::test::expect_valid_output(output, 1, known_defect);
}

TEST(Run, CityJsonFileEveryObjectKeptPartsClosedReportsComplete) {
  MC_REQUIRE_DATA(input, "cjseq/3dbag_b2.city.json");
  mc::test::TempDir dir("run_json");
  const Outputs o = run_on(input, dir, "b2", 2);
  EXPECT_EQ(o.result.buildings, 2u);
  EXPECT_EQ(o.result.counts.at("ok"), 2u);
  EXPECT_EQ(o.result.exit_code(), 0);
  check_output(input, o.output);

  // Run report.
  const json r = json::parse(mc::test::slurp(o.report));
  EXPECT_EQ(r["tool"], "morphcut-city");
  EXPECT_EQ(r["version"], MC_VERSION);
  EXPECT_EQ(r["input"]["sha256"].get<std::string>().size(), 64u);
  EXPECT_EQ(r["input"]["crs"], "EPSG:7415");
  EXPECT_EQ(r["threads"], 2);
  EXPECT_EQ(r["counts"]["ok"], 2);
  EXPECT_EQ(r["config"]["decompose"]["levels"].size(), 4u);
  EXPECT_GT(r["wall_seconds"].get<double>(), 0);
  EXPECT_GT(r["cpu_seconds"].get<double>(), 0);  // every thread's user + system time
  ASSERT_EQ(r["buildings"].size(), 2u);
  for (const auto& b : r["buildings"]) {
    EXPECT_EQ(b["status"], "ok");
    for (const char* k : {"read", "extract", "preprocess", "decompose", "write"})
      EXPECT_TRUE(b["timings"][k].is_number()) << k;
    EXPECT_EQ(b["timings"]["levels"].size(), 4u);
    for (const char* k : {"input_faces", "planes", "cells", "concave_edges"})
      EXPECT_GT(b["sizes"][k].get<double>(), 0) << k;
    ASSERT_EQ(b["levels"].size(), 4u);
    for (const auto& l : b["levels"]) {
      EXPECT_GE(l["parts"].get<int>(), 1);
      EXPECT_TRUE(l["convexity"].is_number());
      EXPECT_TRUE(l["cost"].is_number());
      EXPECT_TRUE(l["nodes_expanded"].is_number());
    }
    EXPECT_TRUE(b["hausdorff"].is_number());
  }

  // Summary CSV: header + one row per building, all the same width; lon/lat near Delft.
  const auto rows = mc::test::parse_csv(mc::test::slurp(o.summary));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0], summary_columns({0.1, 0.01, 0.001, 0.0001}));
  auto col = [&](const std::string& name) {
    return static_cast<size_t>(std::find(rows[0].begin(), rows[0].end(), name) - rows[0].begin());
  };
  for (size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), rows[0].size());
    EXPECT_EQ(rows[i][col("status")], "ok");
    EXPECT_NEAR(std::stod(rows[i][col("lon")]), 4.36, 0.02);
    EXPECT_NEAR(std::stod(rows[i][col("lat")]), 52.00, 0.02);
    EXPECT_GT(std::stod(rows[i][col("volume")]), 100.0);
    EXPECT_GT(std::stod(rows[i][col("parts_0.0001")]), 1.0);
    const double share = std::stod(rows[i][col("largest_part_share")]);
    EXPECT_GT(share, 0.0);
    EXPECT_LE(share, 1.0);
    EXPECT_EQ(rows[i][col("footprint_method")], "ground");
  }
  EXPECT_EQ(mc::test::slurp(o.summary).find("\r\n") != std::string::npos, true);  // RFC 4180 CRLF
}

// The first `n` features of a CityJSONSeq file, as a new file.
std::string head_of_sequence(const std::string& path, size_t n, const std::string& out) {
  std::istringstream in(mc::test::slurp(path));
  std::ofstream o(out);
  std::string line;
  for (size_t i = 0; i <= n && std::getline(in, line); ++i) o << line << "\n";
  return out;
}

// The tool's promise (issue #5): --threads 1 and --threads 2 give byte-identical files. Each run is
// its own process, as users run it.
TEST(Run, ThreadCountDoesNotChangeAByteOfTheOutputs) {
  ASSERT_TRUE(std::filesystem::exists(mc::test::cli_path())) << "build the morphcut_city target first";
  MC_REQUIRE_DATA(tile, "upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20.city.jsonl");
  mc::test::TempDir dir("run_determinism");
  const std::string input = head_of_sequence(tile, 16, dir / "head16.city.jsonl");
  // No deadline (a deadline makes results depend on timing, by design).
  std::ofstream(dir / "det.yaml") << "timeout_s: 0\n";
  for (const char* t : {"1", "2"}) {
    const auto r =
        mc::test::run_command(mc::test::cli_path() + " " + input + " -q --config " + (dir / "det.yaml") +
                              " --threads " + t + " -o " + (dir / (std::string("t") + t + ".city.jsonl")) +
                              " --summary " + (dir / (std::string("t") + t + ".csv")) + " --no-report");
    ASSERT_LE(r.exit_code, 1) << r.output;
  }
  check_output(input, dir / "t1.city.jsonl");
  const std::string a = mc::test::slurp(dir / "t1.city.jsonl"), b = mc::test::slurp(dir / "t2.city.jsonl");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "CityJSONSeq outputs differ between --threads 1 and 2";
  const auto l1 = mc::test::level_files(dir / "t1.city.jsonl"),
             l2 = mc::test::level_files(dir / "t2.city.jsonl");
  ASSERT_EQ(l1.size(), 4u);
  ASSERT_EQ(l2.size(), l1.size());
  for (size_t i = 0; i < l1.size(); ++i)
    EXPECT_TRUE(mc::test::slurp(l1[i]) == mc::test::slurp(l2[i]))
        << l1[i] << " differs between --threads 1 and 2";
  EXPECT_TRUE(mc::test::slurp(dir / "t1.csv") == mc::test::slurp(dir / "t2.csv")) << "summary CSVs differ";
}

// Two runs in one process must agree too (a library user runs many tiles in one process).
// This once failed: CGAL's hull facets come in an address-dependent order and the hull volume
// was summed in that order (fixed in core/hull.cpp).
TEST(Run, RepeatedRunsInOneProcessAreIdentical) {
  MC_REQUIRE_DATA(tile, "upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20.city.jsonl");
  mc::test::TempDir dir("run_repeat");
  const std::string input = head_of_sequence(tile, 16, dir / "head16.city.jsonl");
  const Outputs one = run_on(input, dir, "r1", 1);
  const Outputs two = run_on(input, dir, "r2", 1);
  EXPECT_TRUE(mc::test::slurp(one.output) == mc::test::slurp(two.output));
  const auto l1 = mc::test::level_files(one.output), l2 = mc::test::level_files(two.output);
  ASSERT_FALSE(l1.empty());
  ASSERT_EQ(l1.size(), l2.size());
  for (size_t i = 0; i < l1.size(); ++i)
    EXPECT_TRUE(mc::test::slurp(l1[i]) == mc::test::slurp(l2[i])) << l1[i];
  mc::test::expect_valid_output(one.output);
}

// Jobs start largest first within the look-ahead (docs/design.md, "Largest buildings first");
// outputs keep the input order, and a window as small as one building (FIFO) or two
// (one slot for the building the writer waits for) neither deadlocks nor changes a byte.
TEST(Run, LargestFirstStartsTheLargestAndKeepsTheOutputsInInputOrder) {
  MC_REQUIRE_DATA(tile, "upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20.city.jsonl");
  mc::test::TempDir dir("run_largest_first");
  const std::string input = head_of_sequence(tile, 16, dir / "head16.city.jsonl");
  Params p = mc::test::default_config().params;
  p.dec.levels = {0.1, 0.01};
  p.timeout_s = 0;
  std::vector<std::string> started;
  std::map<std::string, size_t> size;
  std::mutex m;
  auto record = [&](mc::io::Feature& f) {
    std::lock_guard<std::mutex> lock(m);
    started.push_back(f.id);
    size[f.id] = f.vertices.size();
  };
  RunConfig fifo, two, wide;
  fifo.in_flight = 1;
  two.in_flight = 2;
  const Outputs a = run_on(input, dir, "w16", 1, p, wide, record);  // one thread: start order is the schedule
  ASSERT_EQ(started.size(), 16u);
  size_t largest = 0;
  for (const auto& [id, n] : size) largest = std::max(largest, n);
  EXPECT_EQ(size[started.front()], largest) << "the largest building starts first";
  const Outputs b = run_on(input, dir, "w1", 2, p, fifo);
  // The source reads further ahead than the window: with room for two buildings in flight, the
  // largest of the 16 (not of the first two) still starts first.
  started.clear();
  const Outputs c = run_on(input, dir, "w2", 2, p, two, record);
  ASSERT_EQ(started.size(), 16u);
  EXPECT_EQ(size[started.front()], largest) << "the largest of the look-ahead starts first";
  for (const Outputs* o : {&b, &c}) {
    EXPECT_TRUE(mc::test::slurp(a.output) == mc::test::slurp(o->output)) << o->output;
    const auto la = mc::test::level_files(a.output), lo = mc::test::level_files(o->output);
    ASSERT_EQ(la.size(), lo.size());
    for (size_t i = 0; i < la.size(); ++i)
      EXPECT_TRUE(mc::test::slurp(la[i]) == mc::test::slurp(lo[i])) << lo[i];
  }
  // The report lists the buildings in input order. Real 3D BAG solids take the labelling's fast
  // path (docs/algorithm.md §6.6); a building that does not says why.
  const json r = json::parse(mc::test::slurp(a.report));
  size_t fast = 0;
  for (const json& building : r["buildings"]) {
    if (!building.contains("volume_check")) continue;
    const json& vc = building["volume_check"];
    if (vc["fast_path"].get<bool>()) ++fast;
    else EXPECT_FALSE(vc["fast_path_reason"].get<std::string>().empty()) << building["id"];
  }
  EXPECT_GE(fast, 12u);
  // Each job's CPU time (pipeline/job_cpu.hpp), over every thread that worked for it: the
  // two-thread run with a window of two starts buildings out of turn in their own arena.
  const json rc = json::parse(mc::test::slurp(c.report));
  double jobs_cpu = 0;
  for (const json& building : rc["buildings"]) {
    if (!building.contains("timings")) continue;
    const double cpu = building["timings"]["cpu"].get<double>();
    EXPECT_GT(cpu, 0) << building["id"];
    jobs_cpu += cpu;
  }
  EXPECT_GT(jobs_cpu, 0);
  EXPECT_LE(jobs_cpu, 2 * rc["wall_seconds"].get<double>() + 0.05);  // nothing counted twice
  std::istringstream lines(mc::test::slurp(input));
  std::string line;
  std::getline(lines, line);
  for (const json& building : r["buildings"]) {
    ASSERT_TRUE(static_cast<bool>(std::getline(lines, line)));
    EXPECT_EQ(building["id"], json::parse(line)["id"]);
  }
}

TEST(Run, AFailingBuildingIsWrittenThroughAndTheOthersProcessed) {
  MC_REQUIRE_DATA(input, "cjseq/3dbag_b2.city.jsonl");
  mc::test::TempDir dir("run_failure");
  Params p = mc::test::default_config().params;
  p.dec.levels = {0.1, 0.01};
  // The input's first building is broken (jobs start largest first, so not necessarily first).
  std::string broken;
  {
    std::istringstream lines(mc::test::slurp(input));
    std::string line;
    std::getline(lines, line);  // the header
    std::getline(lines, line);
    broken = json::parse(line)["id"].get<std::string>();
  }
  const Outputs o = run_on(input, dir, "f", 2, p, {}, [&](mc::io::Feature& f) {
    if (f.id != broken) return;
    for (auto& v : f.vertices) v.z = 0;  // flattened: nothing inside, the job fails
  });
  EXPECT_EQ(o.result.counts.at("failed"), 1u);
  EXPECT_EQ(o.result.counts.at("ok"), 1u);
  EXPECT_EQ(o.result.exit_code(), 1);
  const json out = mc::test::load_outputs(o.output);
  const json& b = out["CityObjects"][broken];
  EXPECT_EQ(b["attributes"]["morphcut_status"], "failed");
  EXPECT_FALSE(b["attributes"]["morphcut_reason"].get<std::string>().empty());
  for (const auto& c : b["children"]) EXPECT_EQ(c.get<std::string>().find("-mc"), std::string::npos);
  size_t parts = 0;
  for (auto it = out["CityObjects"].begin(); it != out["CityObjects"].end(); ++it)
    parts += it.key().find("-mc") != std::string::npos;
  EXPECT_GE(parts, 2u);                     // the other building's parts
  mc::test::expect_valid_output(o.output);  // the failed building is a note, not an error
  const json r = json::parse(mc::test::slurp(o.report));
  EXPECT_EQ(r["counts"]["failed"], 1);
  EXPECT_EQ(r["buildings"][0]["status"], "failed");
  EXPECT_TRUE(r["buildings"][0].contains("reason"));
  const auto rows = mc::test::parse_csv(mc::test::slurp(o.summary));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1][1], "failed");
  EXPECT_FALSE(rows[1][2].empty());
}

TEST(Run, OutputLevelsAndLodSelectWhatIsWritten) {
  MC_REQUIRE_DATA(input, "cjseq/3dbag_b2.city.json");
  mc::test::TempDir dir("run_levels");
  const LoadedConfig cfg =
      load_config_string("decompose:\n  levels: [0.1, 0.01]\noutput_levels: [0.01]\nlod: \"2.2\"\n");
  const Outputs o = run_on(input, dir, "l", 2, cfg.params, cfg.run);
  EXPECT_EQ(o.result.counts.at("ok"), 2u);
  const json out = mc::test::load_outputs(o.output);
  size_t level1 = 0;
  for (auto it = out["CityObjects"].begin(); it != out["CityObjects"].end(); ++it) {
    EXPECT_EQ(it.key().find("-mc0-"), std::string::npos) << "level 0 not requested";
    level1 += it.key().find("-mc1-") != std::string::npos;
  }
  EXPECT_GT(level1, 2u);
  mc::test::expect_valid_output(o.output);
  const auto rows = mc::test::parse_csv(mc::test::slurp(o.summary));
  EXPECT_EQ(rows[0], summary_columns({0.01}));
}

TEST(Run, UnreadableInputAndUnwritableOutputThrowAndLeaveNothing) {
  mc::test::TempDir dir("run_errors");
  RunOptions opt;
  opt.input = dir / "missing.city.json";
  opt.output = dir / "out.city.json";
  EXPECT_THROW(run_city(opt, Params{}, RunConfig{}), mc::io::ReadError);
  MC_REQUIRE_DATA(input, "cjseq/3dbag_b2.city.json");
  opt.input = input;
  opt.output = dir / "no/such/dir/out.city.json";
  EXPECT_THROW(run_city(opt, Params{}, RunConfig{}), mc::io::WriteError);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path));
}

}  // namespace
}  // namespace mc::pipeline

namespace mc::pipeline {
namespace {

// Two 3D BAG buildings whose reconstructed solids touch themselves along an edge at the coarse
// levels: such parts must never be written (a CityJSON Solid must be a closed 2-manifold); a
// valid stand-in level is written instead and the status says so.
TEST(Run, PartsThatAreNotClosedManifoldsAreNeverWritten) {
  MC_REQUIRE_DATA(tile, "upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20.city.jsonl");
  mc::test::TempDir dir("run_manifold");
  {
    std::istringstream in(mc::test::slurp(tile));
    std::ofstream out(dir / "two.city.jsonl");
    std::string line;
    std::getline(in, line);
    out << line << "\n";
    while (std::getline(in, line))
      if (line.find("\"id\":\"NL.IMBAG.Pand.0503100000019693\"") != std::string::npos ||
          line.find("\"id\":\"NL.IMBAG.Pand.0503100000033695\"") != std::string::npos)
        out << line << "\n";
  }
  const Outputs o = run_on(dir / "two.city.jsonl", dir, "m", 2);
  ASSERT_EQ(o.result.buildings, 2u);
  EXPECT_EQ(o.result.counts.at("failed"), 0u);
  // Every written part is a valid solid. 33695's input is pinched at one vertex (val3dity 303 in
  // its own attributes); its singleton cell must not be (carving repairs pinched vertices).
  check_output(dir / "two.city.jsonl", o.output);
  const json r = json::parse(mc::test::slurp(o.report));
  for (const auto& b : r["buildings"]) {
    ASSERT_EQ(b["levels"].size(), 4u);
    if (b["status"] == "partial") {
      EXPECT_NE(b["reason"].get<std::string>().find("written instead"), std::string::npos) << b["reason"];
    }
    for (const auto& l : b["levels"]) EXPECT_GE(l["parts"].get<int>(), 1);
  }
}

}  // namespace
}  // namespace mc::pipeline
