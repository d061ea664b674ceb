// The HTML report (report/html_report.hpp) from real outputs: run_city on two 3D BAG
// buildings, then the page: inline data agreeing with the report and the city files, no script or
// stylesheet from a URL, deterministic bytes, made from city files alone and from a merged report.
#include <regex>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "io/errors.hpp"
#include "report/html_assets.hpp"
#include "report/html_report.hpp"
#include "report/merge_reports.hpp"
#include "tests/pipeline/pipeline_fixtures.hpp"
#include "pipeline/run.hpp"

namespace {

using nlohmann::json;
using namespace mc::pipeline;
using namespace mc::massing;
using namespace mc::output;
using namespace mc::report;

// The page's inline data (script#mc-data), parsed.
json page_data(const std::string& html) {
  const std::string open = "<script type=\"application/json\" id=\"mc-data\">";
  const size_t a = html.find(open);
  if (a == std::string::npos) return nullptr;
  const size_t b = html.find("</script>", a);
  return json::parse(html.substr(a + open.size(), b - a - open.size()));
}

struct B2Run {
  std::string output, report;
  json report_json;
};

B2Run run_b2(const mc::test::TempDir& dir, const std::string& input) {
  B2Run r;
  r.output = dir / "b2.morphcut.city.json";
  r.report = dir / "b2.morphcut.report.json";
  RunOptions opt;
  opt.input = input;
  opt.output = r.output;
  opt.report = r.report;
  mc::Params p = mc::test::default_config().params;
  p.threads = 2;
  run_city(opt, p, mc::test::default_config().run);
  r.report_json = json::parse(mc::test::slurp(r.report));
  return r;
}

TEST(HtmlReport, PageFromRealOutputsIsSelfContainedAndAgreesWithTheReport) {
  MC_REQUIRE_DATA(input, "3dbag/3dbag_b2.city.json");
  const mc::test::TempDir dir("html_report");
  const B2Run run = run_b2(dir, input);

  // The report names its city outputs (the annotated input, and one file per level when written so).
  const std::vector<std::string> cities = city_files_of_report(run.report);
  ASSERT_FALSE(cities.empty());
  EXPECT_EQ(cities[0], run.output);

  const std::string page = dir / "b2.morphcut.html";
  EXPECT_EQ(html_path_for_report(run.report), page);
  const HtmlReportResult res = write_html_report(run.report, {}, page);
  EXPECT_EQ(res.path, page);
  EXPECT_EQ(res.buildings, 2u);
  EXPECT_EQ(res.with_3d, 2u);
  EXPECT_EQ(res.city_files, cities);
  const std::string html = mc::test::slurp(page);
  EXPECT_EQ(res.bytes, html.size());

  // Self-contained: no script, stylesheet, image or frame from anywhere; a CSP forbidding requests.
  EXPECT_FALSE(std::regex_search(html, std::regex(R"(<script[^>]*\ssrc\s*=)", std::regex::icase)));
  EXPECT_FALSE(std::regex_search(html, std::regex(R"(<link[^>]*href\s*=)", std::regex::icase)));
  EXPECT_FALSE(
      std::regex_search(html, std::regex(R"((src|href)\s*=\s*["']?(https?:)?//)", std::regex::icase)));
  EXPECT_FALSE(std::regex_search(html, std::regex(R"(@import|url\(\s*["']?https?:)", std::regex::icase)));
  EXPECT_NE(html.find("Content-Security-Policy\" content=\"default-src 'none'"), std::string::npos);
  if (html_assets::kHasThree) {
    EXPECT_NE(html.find("var THREE = "), std::string::npos);
    EXPECT_NE(html.find("Permission is hereby granted, free of charge"),
              std::string::npos);  // three's MIT licence
  }

  // Inline data agrees with the report: every building, its status and parts per level; 3D
  // geometry with every level's parts (ids from the city file) and the input ghost.
  const json data = page_data(html);
  ASSERT_TRUE(data.is_object());
  const json& meta = data["meta"];
  EXPECT_EQ(meta["kind"], "run");
  EXPECT_EQ(meta["input"]["sha256"], run.report_json["input"]["sha256"]);
  EXPECT_EQ(meta["wall_seconds"], run.report_json["wall_seconds"]);
  EXPECT_EQ(meta["config_sha256"].get<std::string>().size(), 64u);
  const json& levels = meta["levels"];
  ASSERT_EQ(levels, run.report_json["config"]["decompose"]["levels"]);
  ASSERT_EQ(data["buildings"].size(), run.report_json["buildings"].size());
  const json city = mc::test::load_city(run.output);
  for (size_t i = 0; i < data["buildings"].size(); ++i) {
    const json& b = data["buildings"][i];
    const json& e = run.report_json["buildings"][i];
    EXPECT_EQ(b["id"], e["id"]);
    EXPECT_EQ(b["s"], e["status"]);
    EXPECT_TRUE(b.contains("fp")) << "footprint of " << b["id"];
    ASSERT_TRUE(b.contains("g"));
    const json& g = data["geometry"][b["g"].get<size_t>()];
    EXPECT_FALSE(g["ghost"].empty());
    const size_t vertices = g["v"].size() / 3;
    EXPECT_EQ(g["v"].size() % 3, 0u);
    for (size_t k = 0; k < e["levels"].size(); ++k) {
      const json& level = e["levels"][k];
      EXPECT_EQ(b["p"][k], level["parts"]);
      const json& parts = g["l"][k];
      ASSERT_TRUE(parts.is_array());
      ASSERT_EQ(parts.size(), level["parts"].get<size_t>());
      for (const json& part : parts) {
        // [index, volume, convexity, neighbours, role, id, faces]; every face index a vertex
        ASSERT_EQ(part.size(), 7u);
        bool found = false;
        for (const auto& file : cities) {
          const json c = file == run.output ? city : mc::test::load_city(file);
          found = found || c["CityObjects"].contains(part[5].get<std::string>());
        }
        EXPECT_TRUE(found) << part[5];
        EXPECT_GE(part[6].size(), 4u);
        for (const json& face : part[6]) {
          const json rings = face[0].is_number() ? json::array({face}) : face;
          for (const json& ring : rings)
            for (const json& idx : ring) EXPECT_LT(idx.get<size_t>(), vertices);
        }
      }
    }
  }

  // Deterministic: the same inputs give the same bytes.
  const std::string again = dir / "again.html";
  write_html_report(run.report, {}, again);
  EXPECT_EQ(mc::test::slurp(again), html);

  // Without a report: the city files' morphcut_* attributes and parts.
  const std::string alone = dir / "alone.html";
  const HtmlReportResult r2 = write_html_report("", cities, alone);
  EXPECT_EQ(r2.buildings, 2u);
  const json d2 = page_data(mc::test::slurp(alone));
  EXPECT_EQ(d2["meta"]["kind"], "city");
  EXPECT_EQ(d2["meta"]["levels"], levels);
  for (size_t i = 0; i < d2["buildings"].size(); ++i) {
    EXPECT_EQ(d2["buildings"][i]["s"], data["buildings"][i]["s"]);
    EXPECT_EQ(d2["buildings"][i]["p"], data["buildings"][i]["p"]);
  }

  // A merged report finds each tile's city files through the tile's report.
  MergeOptions mo;
  mo.tiles.push_back(TileReport{"b2", run.report, ""});
  mo.report_out = dir / "merged.report.json";
  merge_reports(mo);
  EXPECT_EQ(city_files_of_report(mo.report_out), cities);
  const std::string merged = dir / "merged.html";
  const HtmlReportResult r3 = write_html_report(mo.report_out, {}, merged);
  EXPECT_EQ(r3.buildings, 2u);
  EXPECT_EQ(r3.with_3d, 2u);
  const json d3 = page_data(mc::test::slurp(merged));
  EXPECT_EQ(d3["meta"]["kind"], "merged");
  EXPECT_EQ(d3["tiles"], json::array({"b2"}));

  // The 3D bound: one building embedded, the other keeps its row and footprint.
  HtmlReportOptions small;
  small.max_3d_buildings = 1;
  const HtmlReportResult r4 = write_html_report(run.report, {}, dir / "bounded.html", small);
  EXPECT_EQ(r4.with_3d, 1u);
  EXPECT_EQ(r4.footprints, 2u);
  HtmlReportOptions tiny;
  tiny.max_3d_bytes = 1;  // the byte budget: no building's geometry fits
  const HtmlReportResult r5 = write_html_report(run.report, {}, dir / "tiny.html", tiny);
  EXPECT_EQ(r5.with_3d, 0u);
  EXPECT_EQ(r5.buildings, 2u);
}

// The CLI: the run writes the page beside its report by default and prints its path and time;
// --no-html writes none; `morphcut-city html` remakes the same bytes from the outputs.
TEST(HtmlReport, CliWritesThePageByDefaultAndTheSubcommandRemakesIt) {
  using mc::test::cli_path;
  using mc::test::run_command;
  ASSERT_TRUE(mc::test::fs::exists(cli_path())) << cli_path() << " missing: build morphcut_city first";
  MC_REQUIRE_DATA(input, "3dbag/3dbag_b2.city.jsonl");
  const mc::test::TempDir dir("html_cli");
  {
    std::ofstream cfg(dir / "quick.yaml");
    cfg << "decompose:\n  levels: [0.1, 0.01]\n";
  }
  mc::test::fs::create_directories(dir.path / "out");
  mc::test::fs::create_directories(dir.path / "none");
  const auto r = run_command("cd " + dir.path.string() + " && " + cli_path() + " " + input +
                             " --config quick.yaml --threads 2 -o out/tile.morphcut.city.jsonl");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const std::string page = dir / "out/tile.morphcut.html";
  ASSERT_TRUE(mc::test::fs::exists(page)) << r.output;
  EXPECT_NE(r.output.find("HTML page"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("of the run's"), std::string::npos) << r.output;  // its time vs the run's
  EXPECT_NE(r.output.find(page.substr(dir.path.string().size() + 1)), std::string::npos) << r.output;
  const json data = page_data(mc::test::slurp(page));
  EXPECT_EQ(data["buildings"].size(), 2u);
  EXPECT_EQ(data["geometry"].size(), 2u);

  const auto h = run_command("cd " + dir.path.string() + " && " + cli_path() +
                             " html out/tile.morphcut.report.json -o again.html");
  EXPECT_EQ(h.exit_code, 0) << h.output;
  EXPECT_EQ(mc::test::slurp(dir / "again.html"), mc::test::slurp(page));

  const auto n =
      run_command("cd " + dir.path.string() + " && " + cli_path() + " " + input +
                  " --config quick.yaml --threads 2 -q --no-html -o none/tile.morphcut.city.jsonl");
  EXPECT_EQ(n.exit_code, 0) << n.output;
  EXPECT_TRUE(mc::test::fs::exists(dir / "none/tile.morphcut.report.json"));
  EXPECT_FALSE(mc::test::fs::exists(dir / "none/tile.morphcut.html"));

  const auto bad = run_command(cli_path() + " html " + (dir / "missing.report.json"));
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
}

TEST(HtmlReport, Errors) {
  const mc::test::TempDir dir("html_report_errors");
  EXPECT_THROW(write_html_report(dir / "missing.report.json", {}, dir / "x.html"), mc::io::ReadError);
  EXPECT_THROW(write_html_report("", {dir / "missing.city.json"}, dir / "x.html"), mc::io::ReadError);
  EXPECT_EQ(html_path_for_report("out/5910.morphcut.report.json"), "out/5910.morphcut.html");
  EXPECT_EQ(html_path_for_report("r.json"), "r.json.html");
}

}  // namespace
