// The output validates against the official CityJSON 2.0 schema (ajv-cli, installed by
// tools/setup-deps.sh into build/node_tools; skipped with a message when it is not there).
#include "pipeline_fixtures.hpp"

namespace mc::test {
namespace {

TEST(Schema, OutputValidatesAgainstCityJson20) {
  const std::string ajv = ajv_path();
  if (ajv.empty())
    GTEST_SKIP() << "ajv-cli not installed (run tools/setup-deps.sh, which puts it in build/node_tools): "
                    "schema validation of the output NOT checked";
  if (!fs::exists(schema_dir() + "/cityjson.min.schema.json")) GTEST_SKIP() << "CityJSON 2.0 schema not found";
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
  // The output has to be a real decomposition for the check to mean anything.
  const json out = json::parse(slurp(dir / "out.city.json"));
  size_t parts = 0;
  for (auto it = out["CityObjects"].begin(); it != out["CityObjects"].end(); ++it) parts += it.key().find("-mc") != std::string::npos;
  ASSERT_GT(parts, 2u);
  expect_valid_output(dir / "out.city.json", parts);
  // A deliberately broken copy must be rejected, or a pass proves nothing. One ajv call for both
  // files: compiling the 300 kB schema is most of ajv's time.
  json broken = out;
  for (auto it = broken["CityObjects"].begin(); it != broken["CityObjects"].end(); ++it)
    if (it.key().find("-mc") != std::string::npos) it.value()["type"] = "NotACityObjectType";
  std::ofstream(dir / "broken.city.json") << broken.dump();
  const std::string cmd = ajv + " validate --strict=false --all-errors=false -c ajv-formats -s " + schema_dir() +
                          "/cityjson.min.schema.json -d " + (dir / "out.city.json") + " -d " + (dir / "broken.city.json");
  const ProcessResult v = run_command(cmd);
  EXPECT_NE(v.output.find("out.city.json valid"), std::string::npos) << cmd << "\n" << v.output.substr(0, 4000);
  EXPECT_NE(v.output.find("broken.city.json invalid"), std::string::npos) << v.output.substr(0, 2000);
}

}  // namespace
}  // namespace mc::test
