// The output validates against the official CityJSON 2.0 schema (ajv-cli, installed by
// tools/setup-deps.sh into build/node_tools; skipped with a message when it is not there).
#include "tests/pipeline/pipeline_fixtures.hpp"

namespace mc::test {
namespace {

TEST(Schema, OutputValidatesAgainstCityJson20) {
  const std::string ajv = ajv_path();
  if (ajv.empty())
    GTEST_SKIP() << "ajv-cli not installed (run tools/setup-deps.sh, which puts it in build/node_tools): "
                    "schema validation of the output NOT checked";
  if (!fs::exists(schema_dir() + "/cityjson.min.schema.json"))
    GTEST_SKIP() << "CityJSON 2.0 schema not found";
  ASSERT_TRUE(fs::exists(cli_path())) << "build the morphcut_city target first";
  MC_REQUIRE_DATA(input, "cjseq/3dbag_b2.city.json");
  TempDir dir("schema");
  {
    std::ofstream cfg(dir / "quick.yaml");
    cfg << "decompose:\n  levels: [0.1, 0.001]\n";
  }
  const ProcessResult run = run_command("cd " + dir.path.string() + " && " + cli_path() + " " + input +
                                        " --config quick.yaml -q -o out.city.json --no-report --no-summary");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  // Every file the run wrote: the annotated input and one city per level (docs/output-format.md).
  const std::vector<std::string> files = {"out.city.json", "out.level-0.1.city.json",
                                          "out.level-0.001.city.json"};
  // The level files have to be real decompositions for the check to mean anything.
  size_t parts = 0;
  for (size_t k = 1; k < files.size(); ++k) {
    const json level = json::parse(slurp(dir / files[k]));
    size_t here = 0;
    for (auto it = level["CityObjects"].begin(); it != level["CityObjects"].end(); ++it)
      here += it.key().find("-mc") != std::string::npos;
    EXPECT_GT(here, 0u) << files[k];
    parts += here;
    expect_valid_output(dir / files[k], here);
  }
  ASSERT_GT(parts, 2u);
  // A deliberately broken copy must be rejected, or a pass proves nothing. One ajv call for all
  // files: compiling the 300 kB schema is most of ajv's time.
  json broken = json::parse(slurp(dir / files[2]));
  for (auto it = broken["CityObjects"].begin(); it != broken["CityObjects"].end(); ++it)
    if (it.key().find("-mc") != std::string::npos) it.value()["type"] = "NotACityObjectType";
  std::ofstream(dir / "broken.city.json") << broken.dump();
  std::string cmd = ajv + " validate --strict=false --all-errors=false -c ajv-formats -s " + schema_dir() +
                    "/cityjson.min.schema.json";
  for (const auto& f : files) cmd += " -d " + (dir / f);
  cmd += " -d " + (dir / "broken.city.json");
  const ProcessResult v = run_command(cmd);
  for (const auto& f : files)
    EXPECT_NE(v.output.find(f + " valid"), std::string::npos) << cmd << "\n" << v.output.substr(0, 4000);
  EXPECT_NE(v.output.find("broken.city.json invalid"), std::string::npos) << v.output.substr(0, 2000);
}

}  // namespace
}  // namespace mc::test
