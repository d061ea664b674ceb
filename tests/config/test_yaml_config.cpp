// YAML loading: defaults, every key of lod.yaml, round trip through the JSON echo.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <set>
#include <sstream>

#include "config/config.hpp"

namespace {

const std::string kLodYaml = std::string(MC_SOURCE_DIR) + "/config/lod.yaml";

TEST(YamlConfig, EmptyDocumentGivesDefaults) {
  const auto c = mc::load_config_string("");
  EXPECT_EQ(mc::effective_config_json(c.params, c.run),
            mc::effective_config_json(mc::Params{}, mc::RunConfig{}));
}

TEST(YamlConfig, LodYamlEqualsTheDefaults) {
  const auto c = mc::load_config_file(kLodYaml);
  EXPECT_EQ(mc::effective_config_json(c.params, c.run),
            mc::effective_config_json(mc::Params{}, mc::RunConfig{}));
  const mc::Params d;
  EXPECT_EQ(c.params.dec.levels, d.dec.levels);
  EXPECT_EQ(c.params.pre.cell_size, d.pre.cell_size);
  EXPECT_EQ(c.params.pre.seed, d.pre.seed);
  EXPECT_EQ(c.params.dec.max_children, d.dec.max_children);
  EXPECT_EQ(c.run.in_flight, 0);
  EXPECT_TRUE(c.run.output_levels.empty());
}

// lod.yaml is the key table printed (core/params.def: type, name, default, kind, range, help):
// regenerate it with `morphcut-city --print-config > config/lod.yaml` after changing the table.
TEST(YamlConfig, LodYamlIsTheKeyTablePrinted) {
  std::ifstream in(kLodYaml);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), mc::config_yaml(mc::Params{}, mc::RunConfig{}));
}

// Each key's range comes from the table, and the printed file loads back to the same values.
TEST(YamlConfig, RangesComeFromTheTableAndThePrintedConfigLoadsBack) {
  auto c = mc::load_config_string(
      "decompose:\n  sigma: 1.5\n  levels: [0.2, 0.02]\npreprocess:\n  cell_size: 0.25\n");
  const auto back = mc::load_config_string(mc::config_yaml(c.params, c.run));
  EXPECT_EQ(mc::effective_config_json(back.params, back.run), mc::effective_config_json(c.params, c.run));
  EXPECT_THROW(mc::load_config_string("massing:\n  roof_max_fill: 1.5\n"), mc::ConfigError);
  EXPECT_THROW(mc::load_config_string("preprocess:\n  oracle: magic\n"), mc::ConfigError);
}

// docs/config.md's key tables are the key table printed: every row, in order, as
// `morphcut-city --print-config-reference` writes it (regenerate them with it after changing
// core/params.def).
TEST(YamlConfig, ConfigReferenceTablesAreTheKeyTable) {
  std::ifstream in(std::string(MC_SOURCE_DIR) + "/docs/config.md");
  ASSERT_TRUE(in.good());
  std::stringstream docs;
  docs << in.rdbuf();
  const std::string tables = mc::config_reference_markdown();
  std::istringstream rows(tables);
  for (std::string row; std::getline(rows, row);) {
    if (row.rfind("| `", 0) != 0) continue;
    EXPECT_NE(docs.str().find(row + "\n"), std::string::npos) << row;
  }
  EXPECT_NE(docs.str().find(tables), std::string::npos)
      << "docs/config.md's key tables are not the key table";
  // Every key of the echo has its row.
  const nlohmann::json j = mc::effective_config_json(mc::Params{}, mc::RunConfig{});
  for (const auto& [k, v] : j.items()) {
    if (v.is_object()) {
      for (const auto& [k2, v2] : v.items())
        EXPECT_NE(tables.find("| `" + k2 + "` |"), std::string::npos) << k << "." << k2;
    } else {
      EXPECT_NE(tables.find("| `" + k + "` |"), std::string::npos) << k;
    }
  }
}

// lod.yaml is the documentation of every key: it must list exactly the keys the loader knows.
TEST(YamlConfig, LodYamlListsEveryKey) {
  const YAML::Node root = YAML::LoadFile(kLodYaml);
  const nlohmann::json j = mc::effective_config_json(mc::Params{}, mc::RunConfig{});
  std::set<std::string> in_yaml, in_json;
  for (const auto& kv : root) {
    const std::string k = kv.first.Scalar();
    if (kv.second.IsMap())
      for (const auto& kv2 : kv.second) in_yaml.insert(k + "." + kv2.first.Scalar());
    else in_yaml.insert(k);
  }
  for (const auto& [k, v] : j.items()) {
    if (v.is_object())
      for (const auto& [k2, v2] : v.items()) in_json.insert(k + "." + k2);
    else in_json.insert(k);
  }
  EXPECT_EQ(in_yaml, in_json);
  EXPECT_GE(in_json.size(), 35u);  // 17 preprocess + 12 decompose + 2 top-level + 4 run keys
}

TEST(YamlConfig, ReadsValues) {
  const auto c = mc::load_config_string(R"(
preprocess:
  cell_size: 0.5
  dist_thresh: 0.125
  max_angle_deg: 15
  seed: 18446744073709551615
  up_axis: y
  compute_hausdorff: false
decompose:
  levels: [0.2, 0.02, 0.002]
  cut_mode: HV
  max_children: -1
  node_budget: 5000000000
timeout_s: 12.5
threads: 3
in_flight: 5
lod: 2.2
output_levels: [0.002, 0.2]
log_level: debug
)");
  EXPECT_DOUBLE_EQ(c.params.pre.cell_size, 0.5);
  EXPECT_DOUBLE_EQ(c.params.pre.dist_thresh, 0.125);
  EXPECT_DOUBLE_EQ(c.params.pre.max_angle_deg, 15);
  EXPECT_EQ(c.params.pre.seed, UINT64_MAX);
  EXPECT_EQ(c.params.pre.up_axis, "y");
  EXPECT_FALSE(c.params.pre.compute_hausdorff);
  EXPECT_EQ(c.params.dec.levels, (std::vector<double>{0.2, 0.02, 0.002}));
  EXPECT_EQ(c.params.dec.cut_mode, "HV");
  EXPECT_EQ(c.params.dec.max_children, -1);
  EXPECT_EQ(c.params.dec.node_budget, 5000000000LL);
  EXPECT_DOUBLE_EQ(c.params.timeout_s, 12.5);
  EXPECT_EQ(c.params.threads, 3);
  EXPECT_EQ(c.run.in_flight, 5);
  EXPECT_EQ(c.run.lod, "2.2");
  EXPECT_EQ(c.run.output_levels, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(c.run.log_level, "debug");
  EXPECT_TRUE(mc::writes_level(c.run, 2));
  EXPECT_FALSE(mc::writes_level(c.run, 1));
  // Untouched keys keep their defaults.
  EXPECT_EQ(c.params.pre.min_points, mc::Params{}.pre.min_points);
}

TEST(YamlConfig, AutoAndExplicitResolution) {
  auto c = mc::load_config_string("preprocess: {cell_size: auto, dist_thresh: 0.3}");
  EXPECT_EQ(c.params.pre.cell_size, 0);
  EXPECT_DOUBLE_EQ(c.params.pre.dist_thresh, 0.3);
  const auto j = mc::effective_config_json(c.params, c.run);
  EXPECT_EQ(j["preprocess"]["cell_size"], "auto");
  EXPECT_EQ(j["preprocess"]["dist_thresh"], 0.3);
}

TEST(YamlConfig, EffectiveJsonLoadsBackToTheSameConfig) {
  const auto c = mc::load_config_string(R"(
preprocess: {cell_size: 2, f_d: 0.02, seed: 7, up_axis: z}
decompose: {levels: [0.1, 0.05], sigma: 1, with_bisector: false}
in_flight: 9
output_levels: [0.05]
)");
  const nlohmann::json j = mc::effective_config_json(c.params, c.run);
  const auto back = mc::load_config_string(j.dump(2), "echo");
  EXPECT_EQ(mc::effective_config_json(back.params, back.run), j);
  EXPECT_EQ(j["output_levels"], nlohmann::json::array({0.05}));
  EXPECT_EQ(j["in_flight"], 9);
}

TEST(YamlConfig, InFlightDefaultsToEightTimesTheThreads) {
  const auto c = mc::load_config_string("threads: 3");
  EXPECT_EQ(mc::effective_in_flight(c.run, 3), 24);
  EXPECT_EQ(mc::effective_in_flight(mc::load_config_string("in_flight: 4").run, 3), 4);
}

TEST(YamlConfig, MissingFileIsAConfigError) {
  EXPECT_THROW(mc::load_config_file("/nonexistent/lod.yaml"), mc::ConfigError);
}

// The settings that never change an output come from the key table, and only those are left out
// of what the cache, merge-reports and the HTML page compare.
TEST(YamlConfig, KeysNotAffectingOutputsComeFromTheTable) {
  EXPECT_EQ(mc::keys_not_affecting_outputs(),
            (std::vector<std::string>{"threads", "in_flight", "log_level"}));
  const mc::LoadedConfig cfg = mc::load_config_string("threads: 3\nin_flight: 7\ntimeout_s: 5\n");
  const nlohmann::json all = mc::effective_config_json(cfg.params, cfg.run);
  const nlohmann::json kept = mc::outputs_config_json(all);
  EXPECT_FALSE(kept.contains("threads"));
  EXPECT_FALSE(kept.contains("in_flight"));
  EXPECT_FALSE(kept.contains("log_level"));
  EXPECT_EQ(kept.at("timeout_s"), 5);
  EXPECT_EQ(kept.size() + 3, all.size());
}

}  // namespace
