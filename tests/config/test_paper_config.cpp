// The paper's per-sample NAME.off_config.json files map onto Params.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "config/config.hpp"

namespace fs = std::filesystem;

namespace {

const fs::path kSamples = fs::path(MC_SOURCE_DIR "/../shared/datasets") / "morphcut-samples";

fs::path config_of(const std::string& sample) {
  for (const auto& e : fs::directory_iterator(kSamples / sample))
    if (e.path().filename().string().ends_with("_config.json")) return e.path();
  return {};
}

TEST(PaperConfig, LoadsEverySample) {
  int n = 0;
  for (const auto& dir : fs::directory_iterator(kSamples)) {
    if (!dir.is_directory()) continue;
    const fs::path f = config_of(dir.path().filename().string());
    if (f.empty()) continue;  // sample5, 11, 17 ship none (automatic resolution)
    std::vector<std::string> warnings;
    mc::Params p;
    ASSERT_NO_THROW(p = mc::load_paper_config(f.string(), &warnings)) << f;
    EXPECT_TRUE(warnings.empty()) << f << ": " << (warnings.empty() ? "" : warnings[0]);
    EXPECT_GT(p.pre.cell_size, 0) << f;
    EXPECT_GE(p.dec.levels.size(), 4u) << f;
    EXPECT_EQ(p.dec.max_children, -1) << f;
    EXPECT_DOUBLE_EQ(p.dec.sigma, 2.0) << f;
    ++n;
  }
  EXPECT_GE(n, 14);
}

TEST(PaperConfig, Sample1) {
  const mc::Params p = mc::load_paper_config(config_of("sample1").string());
  EXPECT_DOUBLE_EQ(p.pre.cell_size, 0.1);
  EXPECT_DOUBLE_EQ(p.pre.dist_thresh, 0.05);
  EXPECT_DOUBLE_EQ(p.pre.max_distance, 0.05);
  EXPECT_DOUBLE_EQ(p.pre.max_angle_deg, 30);
  EXPECT_DOUBLE_EQ(p.pre.angle_thresh_deg, 30);
  EXPECT_EQ(p.dec.levels, (std::vector<double>{0.1, 0.01, 0.001, 0.0001, 0.00001}));
  EXPECT_DOUBLE_EQ(p.dec.sigma, 2);
  EXPECT_EQ(p.pre.min_points, 100);
  EXPECT_EQ(p.pre.max_points, 10000);
  EXPECT_TRUE(p.dec.with_bisector);
}

TEST(PaperConfig, OtherSamples) {
  const mc::Params p2 = mc::load_paper_config(config_of("sample2").string());
  EXPECT_DOUBLE_EQ(p2.pre.angle_thresh_deg, 5);  // differs from max_angle in this one
  EXPECT_DOUBLE_EQ(p2.pre.max_angle_deg, 10);
  EXPECT_DOUBLE_EQ(p2.pre.cell_size, 0.5);
  const mc::Params p16 = mc::load_paper_config(config_of("sample16").string());
  EXPECT_EQ(p16.pre.min_points, 10000);
  const mc::Params p20 = mc::load_paper_config(config_of("sample20").string());
  EXPECT_EQ(p20.dec.levels.size(), 4u);
  EXPECT_DOUBLE_EQ(p20.pre.cell_size, 2.0);
  const fs::path f24 = config_of("sample24");
  if (!f24.empty()) { EXPECT_FALSE(mc::load_paper_config(f24.string()).dec.with_bisector); }
}

class PaperFile : public ::testing::Test {
 protected:
  fs::path write(const std::string& text) {
    path_ = fs::temp_directory_path() /
            ("mc_paper_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".json");
    std::ofstream(path_) << text;
    return path_;
  }
  void TearDown() override { fs::remove(path_); }
  fs::path path_;
};

TEST_F(PaperFile, UnknownKeysAreWarningsAndOptionalKeysTakeTheResearchDefaults) {
  std::vector<std::string> w;
  const mc::Params p = mc::load_paper_config(
      write(R"({"cell_size": 1.0, "dist_thresh": 0.5, "max_distance": 0.5, "max_angle": 10,
               "min_region": 1, "angle_thresh": 10, "concave_thresh": 1.0, "min_points": 100,
               "max_points": 10000, "sigma": 2.0, "symmetry": true, "new_thing": 3,
               "cut_mode": "V", "fewer_comp": true})")
          .string(),
      &w);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_NE(w[0].find("new_thing"), std::string::npos);
  EXPECT_NE(w[1].find("symmetry"), std::string::npos);
  EXPECT_EQ(p.dec.levels, (std::vector<double>{0.1, 0.01, 0.001}));
  EXPECT_EQ(p.dec.max_children, -1);
  EXPECT_EQ(p.dec.cut_mode, "V");
}

TEST_F(PaperFile, MissingRequiredKeysAreWarnings) {
  std::vector<std::string> w;
  const mc::Params p = mc::load_paper_config(write(R"({"cell_size": 3})").string(), &w);
  EXPECT_EQ(w.size(), 9u);
  EXPECT_DOUBLE_EQ(p.pre.cell_size, 3);
}

TEST_F(PaperFile, BadValuesNameThePaperKey) {
  auto message = [&](const std::string& json) -> std::string {
    try {
      mc::load_paper_config(write(json).string());
    } catch (const mc::ConfigError& e) { return e.what(); }
    return "accepted";
  };
  EXPECT_EQ(
      message(R"({"min_cut_factor": [0.1, 0.2]})").rfind("min_cut_factor: must be strictly decreasing", 0),
      0u);
  EXPECT_EQ(message(R"({"min_cut_factor": [0.1, -0.2]})").rfind("min_cut_factor[1]: must be in (0, 1]", 0),
            0u);
  EXPECT_EQ(message(R"({"angle_thresh": 95})").rfind("angle_thresh: must be in (0, 90)", 0), 0u);
  EXPECT_EQ(message(R"({"cut_mode": "Z"})").rfind("cut_mode: must be one of", 0), 0u);
  EXPECT_EQ(message(R"({"sigma": "2"})").rfind("sigma: expected a number", 0), 0u);
  EXPECT_EQ(message(R"({"min_points": 1.5})").rfind("min_points: expected an integer", 0), 0u);
  EXPECT_EQ(message(R"({"cell_size": 0})").rfind("cell_size: must be > 0", 0), 0u);
  EXPECT_EQ(message(R"({"with_bisector": 1})").rfind("with_bisector: expected true or false", 0), 0u);
  EXPECT_EQ(message(R"([1, 2])").rfind("(root): expected a JSON object", 0), 0u);
  EXPECT_NE(message(R"({"sigma": )").find("invalid JSON"), std::string::npos);
}

}  // namespace
