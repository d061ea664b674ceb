// merge-reports on real run reports: the binary is run on two small tiles once, then the
// reports are merged as they are, with a tile missing, with a duplicated tile, and with a tile
// from another config.
#include "report/merge_reports.hpp"

#include <fstream>

#include "io/csv.hpp"
#include "io/sha256.hpp"
#include "tests/pipeline/pipeline_fixtures.hpp"

namespace mc::pipeline {
using namespace mc::output;
using namespace mc::report;
namespace {

using mc::test::json;
using mc::test::slurp;
namespace fs = std::filesystem;

void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

class MergeReports : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    a_ = mc::test::data_file("3dbag/3dbag_b2.city.json");
    b_ = mc::test::data_file("3dbag/delft_subset.city.jsonl");
    if (a_.empty() || b_.empty()) return;
    dir_ = new mc::test::TempDir("merge");
    for (const std::string& in : {a_, b_}) {
      const auto r = mc::test::run_command("cd " + dir_->path.string() + " && " + mc::test::cli_path() + " " +
                                           in + " --threads 2 -q");
      ok_ = ok_ && (r.exit_code == 0 || r.exit_code == 1);
      if (!ok_) ADD_FAILURE() << r.output;
    }
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  void SetUp() override {
    if (a_.empty() || b_.empty()) GTEST_SKIP() << "test data not found";
    ASSERT_TRUE(ok_);
  }
  static std::string report(const std::string& stem) { return *dir_ / (stem + ".morphcut.report.json"); }
  static TileReport tile(const std::string& stem) {
    return {stem, report(stem), csv_beside_report(report(stem))};
  }
  static inline std::string a_, b_;
  static inline mc::test::TempDir* dir_ = nullptr;
  static inline bool ok_ = true;
};

TEST(MergeNames, FollowMorphcutCityNaming) {
  EXPECT_EQ(tile_name_of_report("out/5910.morphcut.report.json"), "5910");
  EXPECT_EQ(csv_beside_report("out/5910.morphcut.report.json"), "out/5910.morphcut.csv");
  EXPECT_EQ(csv_beside_report("out/other.json"), "");
  EXPECT_EQ(input_stem("tiles/3dbag_5910.city.jsonl"), "3dbag_5910");
  EXPECT_EQ(input_stem("tiles/x.city.json"), "x");
}

TEST_F(MergeReports, TwoRealTilesMergeIntoOneReportAndCsv) {
  const json ra = json::parse(slurp(report("3dbag_b2"))), rb = json::parse(slurp(report("delft_subset")));
  MergeOptions opt;
  opt.tiles = {tile("3dbag_b2"), tile("delft_subset")};
  opt.report_out = *dir_ / "merged.report.json";
  opt.csv_out = *dir_ / "merged.csv";
  const MergeResult r = merge_reports(opt);
  EXPECT_EQ(r.exit_code(), 0);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  const size_t n = ra["building_count"].get<size_t>() + rb["building_count"].get<size_t>();
  EXPECT_EQ(r.buildings, n);

  const json m = json::parse(slurp(opt.report_out));
  ASSERT_EQ(m["tiles"].size(), 2u);
  EXPECT_EQ(m["tiles"][0]["tile"], "3dbag_b2");
  EXPECT_EQ(m["tiles"][1]["tile"], "delft_subset");
  EXPECT_EQ(m["tiles"][0]["report_sha256"], mc::io::sha256_file(report("3dbag_b2")));
  EXPECT_EQ(m["tiles"][1]["input_sha256"], rb["input"]["sha256"]);
  // Each tile's outputs, its level files among them (docs/output-format.md).
  EXPECT_EQ(m["tiles"][0]["outputs"], ra["outputs"]);
  EXPECT_FALSE(m["tiles"][1]["outputs"]["levels"].empty());
  EXPECT_EQ(m["tiles"][1]["counts"], rb["counts"]);
  EXPECT_EQ(m["totals"]["building_count"], n);
  for (const char* s : {"ok", "partial", "failed", "skipped"})
    EXPECT_EQ(m["totals"]["counts"][s], ra["counts"][s].get<size_t>() + rb["counts"][s].get<size_t>()) << s;
  EXPECT_EQ(m["totals"]["missing"], 0);
  EXPECT_TRUE(m["missing_tiles"].empty());
  EXPECT_TRUE(m["duplicates"].empty());
  ASSERT_EQ(m["buildings"].size(), n);
  // Tile order, then each tile's own order; every entry keeps its fields, with the tile first.
  EXPECT_EQ(m["buildings"][0]["tile"], "3dbag_b2");
  EXPECT_EQ(m["buildings"][0]["id"], ra["buildings"][0]["id"]);
  EXPECT_EQ(m["buildings"][n - 1]["tile"], "delft_subset");
  EXPECT_EQ(m["buildings"][n - 1]["levels"], rb["buildings"].back()["levels"]);

  const auto rows = mc::test::parse_csv(slurp(opt.csv_out));
  const auto rows_a = mc::test::parse_csv(slurp(tile("3dbag_b2").csv));
  ASSERT_EQ(rows.size(), n + 1);
  ASSERT_EQ(rows[0].size(), rows_a[0].size() + 1);
  EXPECT_EQ(rows[0][0], "tile");
  EXPECT_TRUE(std::equal(rows_a[0].begin(), rows_a[0].end(), rows[0].begin() + 1));
  EXPECT_EQ(rows[1][0], "3dbag_b2");
  EXPECT_TRUE(std::equal(rows_a[1].begin(), rows_a[1].end(), rows[1].begin() + 1));
  EXPECT_EQ(rows[n][0], "delft_subset");

  // Deterministic: merging again gives the same bytes.
  const std::string first = slurp(opt.report_out);
  merge_reports(opt);
  EXPECT_EQ(slurp(opt.report_out), first);
}

TEST_F(MergeReports, AMissingTileIsListedAndTheExitCodeIsOne) {
  const std::string list = *dir_ / "tiles.txt";
  write(list, "# three tiles, one never ran\n" + a_ + "\n\n/data/never_ran.city.json\n" + b_ + "\n");
  const std::string out = *dir_ / "with_missing.report.json";
  const auto r =
      mc::test::run_command(mc::test::cli_path() + " merge-reports --tiles " + list + " --dir " +
                            dir_->path.string() + " -o " + out + " --csv " + (*dir_ / "with_missing.csv"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("missing tile never_ran"), std::string::npos) << r.output;
  const json m = json::parse(slurp(out));
  ASSERT_EQ(m["missing_tiles"].size(), 1u);
  EXPECT_EQ(m["missing_tiles"][0]["tile"], "never_ran");
  EXPECT_EQ(m["missing_tiles"][0]["reason"], "report not found");
  EXPECT_EQ(m["totals"]["tiles"], 3);
  EXPECT_EQ(m["totals"]["merged"], 2);
  EXPECT_EQ(m["tiles"].size(), 2u);
  EXPECT_EQ(mc::test::parse_csv(slurp(*dir_ / "with_missing.csv")).size(), m["buildings"].size() + 1);
}

TEST_F(MergeReports, ABuildingInTwoTilesIsReportedAsDuplicate) {
  // The same tile under a second name: every building is on "both tiles".
  fs::copy_file(report("3dbag_b2"), report("b2_copy"), fs::copy_options::overwrite_existing);
  fs::copy_file(tile("3dbag_b2").csv, tile("b2_copy").csv, fs::copy_options::overwrite_existing);
  MergeOptions opt;
  opt.tiles = {tile("3dbag_b2"), tile("delft_subset"), tile("b2_copy")};
  opt.report_out = *dir_ / "dup.report.json";
  const MergeResult r = merge_reports(opt);
  const json ra = json::parse(slurp(report("3dbag_b2")));
  EXPECT_EQ(r.duplicate_ids, ra["buildings"].size());
  const json m = json::parse(slurp(opt.report_out));
  ASSERT_EQ(m["duplicates"].size(), ra["buildings"].size());
  EXPECT_EQ(m["duplicates"][0]["tiles"], json::array({"3dbag_b2", "b2_copy"}));
  EXPECT_EQ(m["totals"]["duplicate_ids"], ra["buildings"].size());
  EXPECT_EQ(m["buildings"].size(), r.buildings);  // both copies kept, each with its tile
}

TEST_F(MergeReports, AnotherVersionOrConfigIsWarnedAndRecorded) {
  json other = json::parse(slurp(report("delft_subset")));
  other["version"] = "0.0.1";
  other["config"]["decompose"]["sigma"] = 123.0;
  other["config"]["threads"] = 64;  // not a result-shaping setting
  write(report("delft_other"), other.dump());
  // Its CSV lacks a column (as with other output levels): rows are mapped by column name.
  auto rows = mc::test::parse_csv(slurp(tile("delft_subset").csv));
  std::string csv;
  for (auto& row : rows) {
    row.erase(row.begin() + 3);  // "lod"
    for (size_t i = 0; i < row.size(); ++i) csv += (i ? "," : "") + mc::io::csv_escape(row[i]);
    csv += "\r\n";
  }
  write(tile("delft_other").csv, csv);
  MergeOptions opt;
  opt.tiles = {tile("3dbag_b2"), tile("delft_other")};
  opt.report_out = *dir_ / "mixed.report.json";
  opt.csv_out = *dir_ / "mixed.csv";
  const MergeResult r = merge_reports(opt);
  EXPECT_EQ(r.exit_code(), 0);
  const json m = json::parse(slurp(opt.report_out));
  EXPECT_EQ(m["tiles"][1]["mismatch"], json::array({"version", "config"}));
  EXPECT_NE(m["tiles"][0]["config_sha256"], m["tiles"][1]["config_sha256"]);
  ASSERT_EQ(m["warnings"].size(), 3u);
  EXPECT_NE(m["warnings"][0].get<std::string>().find("0.0.1"), std::string::npos);
  const auto merged = mc::test::parse_csv(slurp(opt.csv_out));
  EXPECT_EQ(merged[0][4], "lod");
  const size_t first_b = 1 + json::parse(slurp(report("3dbag_b2")))["buildings"].size();
  EXPECT_EQ(merged[first_b][0], "delft_other");
  EXPECT_EQ(merged[first_b][4], "");          // the column it does not have
  EXPECT_EQ(merged[first_b][2], rows[1][1]);  // status, found by name
}

TEST_F(MergeReports, UnreadableReportCountsAsMissing) {
  write(report("broken"), "{\"run\": ");
  MergeOptions opt;
  opt.tiles = {tile("broken"), tile("3dbag_b2")};
  opt.report_out = *dir_ / "broken_merge.report.json";
  const MergeResult r = merge_reports(opt);
  EXPECT_EQ(r.exit_code(), 1);
  ASSERT_EQ(r.missing.size(), 1u);
  EXPECT_NE(r.missing[0].find("not valid JSON"), std::string::npos) << r.missing[0];
}

}  // namespace
}  // namespace mc::pipeline
