// The morphcut-city binary: help, exit codes, default output names, interruption.
#include <signal.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "pipeline_fixtures.hpp"

namespace mc::test {
namespace {

#define MC_REQUIRE_CLI()              \
  ASSERT_TRUE(fs::exists(cli_path())) \
      << cli_path() << " missing: build the morphcut_city target before these tests"

TEST(Cli, HelpIsCompleteAndExitsZero) {
  MC_REQUIRE_CLI();
  const ProcessResult r = run_command(cli_path() + " --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* s :
       {"INPUT", "--config", "--output", "--threads", "--timeout", "--lod", "--report", "--summary",
        "--quiet", "Exit codes", "130", ".morphcut.city.json", ".morphcut.report.json", ".morphcut.csv"})
    EXPECT_NE(r.output.find(s), std::string::npos) << "--help does not mention " << s;
}

// --print-config prints the key table as YAML: with no --config it is config/lod.yaml, and
// --config and the options override it.
TEST(Cli, PrintConfigIsLodYamlAndShowsOverrides) {
  MC_REQUIRE_CLI();
  TempDir dir("cli_print_config");
  const ProcessResult d = run_command(cli_path() + " --print-config 2>/dev/null");
  EXPECT_EQ(d.exit_code, 0);
  EXPECT_EQ(d.output, mc::test::slurp(std::string(MC_SOURCE_DIR) + "/config/lod.yaml"));
  std::ofstream(dir / "c.yaml") << "decompose:\n  sigma: 1.5\n";
  const ProcessResult c = run_command(cli_path() + " --print-config --no-fast-path -c " + (dir / "c.yaml"));
  EXPECT_EQ(c.exit_code, 0);
  EXPECT_NE(c.output.find("  sigma: 1.5 "), std::string::npos) << c.output;
  EXPECT_NE(c.output.find("  fast_path: false "), std::string::npos) << c.output;
}

// --print-config-reference prints docs/config.md's key tables, without an input.
TEST(Cli, PrintConfigReferenceIsTheDocsTables) {
  MC_REQUIRE_CLI();
  const ProcessResult r = run_command(cli_path() + " --print-config-reference 2>/dev/null");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output.find("| `storey_min_cover` | number | 0.9 | [0, 1] |"), std::string::npos) << r.output;
  EXPECT_NE(mc::test::slurp(std::string(MC_SOURCE_DIR) + "/docs/config.md").find(r.output),
            std::string::npos);
}

TEST(Cli, UsageConfigAndReadErrorsExitTwo) {
  MC_REQUIRE_CLI();
  TempDir dir("cli_errors");
  EXPECT_EQ(run_command(cli_path()).exit_code, 2);                                // no INPUT
  EXPECT_EQ(run_command(cli_path() + " x.city.json --threads -1").exit_code, 2);  // bad value
  EXPECT_EQ(run_command(cli_path() + " x.city.json --bogus").exit_code, 2);       // unknown option
  const ProcessResult missing =
      run_command("cd " + dir.path.string() + " && " + cli_path() + " missing.city.json");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("missing.city.json"), std::string::npos) << missing.output;
  {
    std::ofstream bad(dir / "bad.yaml");
    bad << "decompose:\n  sigma: [1]\n  bogus_key: 3\n";
  }
  MC_REQUIRE_DATA(input, "cjseq/3dbag_b2.city.json");
  const ProcessResult cfg =
      run_command("cd " + dir.path.string() + " && " + cli_path() + " " + input + " --config bad.yaml");
  EXPECT_EQ(cfg.exit_code, 2);
  EXPECT_NE(cfg.output.find("decompose."), std::string::npos) << cfg.output;
  EXPECT_TRUE(fs::is_empty(dir.path) || !fs::exists(dir / "3dbag_b2.morphcut.city.json"));
}

TEST(Cli, DefaultOutputNamesInTheCurrentDirectory) {
  MC_REQUIRE_CLI();
  MC_REQUIRE_DATA(input, "cjseq/3dbag_b2.city.jsonl");
  TempDir dir("cli_defaults");
  {
    std::ofstream cfg(dir / "quick.yaml");
    cfg << "decompose:\n  levels: [0.1]\n";
  }
  const ProcessResult r = run_command("cd " + dir.path.string() + " && " + cli_path() + " " + input +
                                      " --config quick.yaml --threads 2");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("2 ok"), std::string::npos) << r.output;  // the final summary line
  EXPECT_TRUE(fs::exists(dir / "3dbag_b2.morphcut.city.jsonl"));
  EXPECT_TRUE(fs::exists(dir / "3dbag_b2.morphcut.level-0.1.city.jsonl"));  // one city per level
  EXPECT_TRUE(fs::exists(dir / "3dbag_b2.morphcut.report.json"));
  EXPECT_TRUE(fs::exists(dir / "3dbag_b2.morphcut.csv"));
  const json report = json::parse(slurp(dir / "3dbag_b2.morphcut.report.json"));
  EXPECT_EQ(report["config_file"], "quick.yaml");
  EXPECT_EQ(report["config"]["decompose"]["levels"], json::array({0.1}));
  // The output passes the binary's own validator (exit 0 = every object valid).
  const ProcessResult v = run_command(cli_path() + " validate " + (dir / "3dbag_b2.morphcut.city.jsonl"));
  EXPECT_EQ(v.exit_code, 0) << v.output;
  const ProcessResult vl =
      run_command(cli_path() + " validate " + (dir / "3dbag_b2.morphcut.level-0.1.city.jsonl"));
  EXPECT_EQ(vl.exit_code, 0) << vl.output;
  EXPECT_EQ(report["outputs"]["levels"][0]["cityjson"], "3dbag_b2.morphcut.level-0.1.city.jsonl");
  // --quiet: nothing on stderr for a clean run.
  const ProcessResult q = run_command("cd " + dir.path.string() + " && " + cli_path() + " " + input +
                                      " --config quick.yaml -q -o q.city.jsonl --no-report --no-summary");
  EXPECT_EQ(q.exit_code, 0);
  EXPECT_EQ(q.output, "");
  EXPECT_TRUE(fs::exists(dir / "q.city.jsonl"));
  expect_valid_output(dir / "q.city.jsonl");
  // With -o, the report and the summary go beside the output, not into the current directory.
  fs::create_directories(dir.path / "cwd");
  fs::create_directories(dir.path / "out");
  const ProcessResult o =
      run_command("cd " + (dir.path / "cwd").string() + " && " + cli_path() + " " + input +
                  " --config ../quick.yaml -q -o ../out/tile.morphcut.city.jsonl");
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_TRUE(fs::exists(dir.path / "out" / "tile.morphcut.city.jsonl"));
  EXPECT_TRUE(fs::exists(dir.path / "out" / "tile.morphcut.report.json"));
  EXPECT_TRUE(fs::exists(dir.path / "out" / "tile.morphcut.csv"));
  EXPECT_TRUE(fs::is_empty(dir.path / "cwd"));
}

// log_level (config) decides what the run prints on stderr: the summary at info, nothing of a
// clean run at warn; an error is printed at any level but off.
TEST(Cli, LogLevelSetsWhatReachesStderr) {
  MC_REQUIRE_CLI();
  MC_REQUIRE_DATA(input, "cjseq/3dbag_b2.city.jsonl");
  TempDir dir("cli_log_level");
  for (const char* level : {"info", "warn", "off"})
    std::ofstream(dir / (std::string(level) + ".yaml"))
        << "decompose:\n  levels: [0.1]\nlog_level: " << level << "\n";
  auto run = [&](const std::string& level, const std::string& in) {
    return run_command("cd " + dir.path.string() + " && " + cli_path() + " " + in + " --config " + level +
                       ".yaml --no-html -o out.city.jsonl");
  };
  const ProcessResult info = run("info", input);
  EXPECT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("morphcut-city: 2 buildings"), std::string::npos) << info.output;
  const ProcessResult warn = run("warn", input);
  EXPECT_EQ(warn.exit_code, 0) << warn.output;
  EXPECT_EQ(warn.output, "");
  const ProcessResult missing = run("warn", "missing.city.jsonl");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("morphcut-city: cannot read input"), std::string::npos) << missing.output;
  EXPECT_EQ(run("off", "missing.city.jsonl").output, "");
}

TEST(Cli, StdinIsReadAsCityJsonSeq) {
  MC_REQUIRE_CLI();
  MC_REQUIRE_DATA(input, "cjseq/3dbag_b2.city.jsonl");
  TempDir dir("cli_stdin");
  {
    std::ofstream cfg(dir / "quick.yaml");
    cfg << "decompose:\n  levels: [0.1]\n";
  }
  const ProcessResult r =
      run_command("cd " + dir.path.string() + " && " + cli_path() + " - --config quick.yaml -q < " + input);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const json report = json::parse(slurp(dir / "stdin.morphcut.report.json"));
  EXPECT_EQ(report["counts"]["ok"], 2);
  EXPECT_TRUE(report["input"]["sha256"].is_null());
  EXPECT_TRUE(fs::exists(dir / "stdin.morphcut.city.jsonl"));
  expect_valid_output(dir / "stdin.morphcut.city.jsonl");
}

// SIGINT / SIGTERM in the middle of a tile: exit 130 / 143, no output, no temp file.
void interrupt_midway(int sig) {
  MC_REQUIRE_CLI();
  MC_REQUIRE_DATA(input, "upgraded-2.0/3dbag_v210908_fd2cee53_5910.v20.city.jsonl");
  TempDir dir(std::string("cli_signal") + std::to_string(sig));
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (chdir(dir.path.c_str()) != 0) _exit(99);
    int devnull = ::open("/dev/null", O_WRONLY);
    dup2(devnull, 1), dup2(devnull, 2);
    execl(cli_path().c_str(), "morphcut-city", input.c_str(), "--threads", "2", "-q",
          static_cast<char*>(nullptr));
    _exit(98);
  }
  // Wait until the outputs' temp files exist (the run is under way), then interrupt.
  bool started = false;
  for (int i = 0; i < 200 && !started; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    for (const auto& e : fs::directory_iterator(dir.path))
      started = started || e.path().filename().string().find(".tmp.") != std::string::npos;
  }
  EXPECT_TRUE(started);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  kill(pid, sig);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 128 + sig);
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir.path)) left.push_back(e.path().filename().string());
  EXPECT_TRUE(left.empty()) << "left behind: " << (left.empty() ? "" : left.front());
}

TEST(Cli, SigintStopsCleanlyWithExit130) { interrupt_midway(SIGINT); }
TEST(Cli, SigtermStopsCleanlyWithExit143) { interrupt_midway(SIGTERM); }

// On a terminal the progress line shows done/total and an ETA whenever the reader knows how many
// features come: CityJSON (the document's first pass), CityJSONSeq (lines counted) and CityGML
// (its first pass). `script` gives the run a pseudo-terminal.
TEST(Cli, ProgressOnATerminalShowsTheTotalAndAnEta) {
  if (run_command("command -v script").exit_code != 0) GTEST_SKIP() << "script (bsdutils) not installed";
  TempDir dir("progress_tty");
  const std::string gml = std::string(MC_SOURCE_DIR) + "/../shared/datasets/citygml/LOD2_Buildings_v200.gml";
  std::vector<std::pair<std::string, std::string>> inputs = {
      {data_file("3dbag/3dbag_5910.city.json"), "/432 features"},
      {data_file("cjseq/3dbag_b2.city.jsonl"), "/2 features"}};
  if (fs::exists(gml)) inputs.push_back({gml, "/100 features"});
  for (const auto& [input, total] : inputs) {
    if (input.empty()) continue;
    SCOPED_TRACE(input);
    const std::string cmd = cli_path() + " '" + input + "' --lod 9 --threads 2 --no-html -o '" + dir / "out" +
                            (input.ends_with(".jsonl") ? ".city.jsonl" : ".city.json") + "'";
    const ProcessResult r = run_command("script -qec \"" + cmd + "\" /dev/null");
    EXPECT_NE(r.output.find(total), std::string::npos) << r.output.substr(0, 2000);
    EXPECT_NE(r.output.find("ETA"), std::string::npos) << r.output.substr(0, 2000);
  }
}

}  // namespace
}  // namespace mc::test
