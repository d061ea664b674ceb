// Every rejection names the key path (and the line), so users can fix their file.
#include <gtest/gtest.h>

#include "config/config.hpp"

namespace {

struct Bad {
  const char* yaml;
  const char* message;  // expected prefix of what()
};

// Readable (and stable) test names in ctest instead of the struct's bytes.
void PrintTo(const Bad& b, std::ostream* os) {
  *os << std::string(b.message).substr(0, std::string(b.message).find(':'));
}

class Rejects : public ::testing::TestWithParam<Bad> {};

TEST_P(Rejects, WithTheKeyPath) {
  const Bad& b = GetParam();
  try {
    mc::load_config_string(b.yaml, "test.yaml");
    FAIL() << "accepted: " << b.yaml;
  } catch (const mc::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(b.message, 0), 0u) << "what(): " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Config, Rejects,
    ::testing::Values(
        Bad{"decompose:\n  levels: [0.1, 0.1, 0.01]\n",
            "decompose.levels: must be strictly decreasing (test.yaml:2)"},
        Bad{"decompose:\n  levels: [0.01, 0.1]\n", "decompose.levels: must be strictly decreasing"},
        Bad{"decompose:\n  levels: []\n", "decompose.levels: must not be empty"},
        Bad{"decompose:\n  levels: [0.1, 1.5]\n", "decompose.levels[1]: must be in (0, 1]"},
        Bad{"decompose:\n  levels: [0.1, x]\n", "decompose.levels[1]: expected a number, got 'x'"},
        Bad{"decompose:\n  levels: 0.1\n", "decompose.levels: expected a list of numbers"},
        Bad{"preprocess:\n  angle_thresh_deg: 90\n",
            "preprocess.angle_thresh_deg: must be in (0, 90), got 90 (test.yaml:2)"},
        Bad{"preprocess:\n  max_angle_deg: 0\n", "preprocess.max_angle_deg: must be in (0, 90)"},
        Bad{"preprocess:\n  cel_size: 1\n",
            "preprocess.cel_size: unknown key (did you mean 'cell_size'?) (test.yaml:2)"},
        Bad{"preprocess:\n  zzz: 1\n", "preprocess.zzz: unknown key (test.yaml:2)"},
        Bad{"decompos:\n  sigma: 1\n", "decompos: unknown key (did you mean 'decompose'?)"},
        Bad{"timeout: 5\n", "timeout: unknown key (did you mean 'timeout_s'?)"},
        Bad{"decompose:\n  cut_mode: X\n", "decompose.cut_mode: must be one of A, H, V, HV, HI, VI, got 'X'"},
        Bad{"decompose:\n  sigma: fast\n", "decompose.sigma: expected a number, got 'fast'"},
        Bad{"decompose:\n  sigma: .nan\n", "decompose.sigma: expected a number"},
        Bad{"decompose:\n  k: 2.5\n", "decompose.k: expected an integer, got '2.5'"},
        Bad{"decompose:\n  max_children: 0\n", "decompose.max_children: must be -1 (keep all) or >= 1"},
        Bad{"decompose:\n  with_bisector: maybe\n",
            "decompose.with_bisector: expected true or false, got 'maybe'"},
        Bad{"decompose:\n  concave_thresh: 0.5\n", "decompose.concave_thresh: must be in [1, 2)"},
        Bad{"decompose:\n  node_budget: 0\n", "decompose.node_budget: must be >= 1"},
        Bad{"decompose:\n  revisit_candidates: -1\n", "decompose.revisit_candidates: must be >= 0 (0 = all)"},
        Bad{"decompose:\n  first_level_candidates: -2\n",
            "decompose.first_level_candidates: must be >= -1 (-1 = max_candidates, 0 = all)"},
        Bad{"decompose:\n  revisit_boundaries: 3\n",
            "decompose.revisit_boundaries: expected true or false, got '3'"},
        Bad{"decompose:\n  uncut_convexity: 0\n", "decompose.uncut_convexity: must be in (0, 1]"},
        Bad{"decompose: [1, 2]\n", "decompose: expected a mapping of keys, got a list"},
        Bad{"preprocess:\n  cell_size: 0\n", "preprocess.cell_size: must be > 0 or auto"},
        Bad{"preprocess:\n  cell_size: -1\n", "preprocess.cell_size: must be > 0 or auto"},
        Bad{"preprocess:\n  cell_size:\n", "preprocess.cell_size: missing value"},
        Bad{"preprocess:\n  seed: -1\n", "preprocess.seed: expected a non-negative integer, got '-1'"},
        Bad{"preprocess:\n  min_points: 20000\n", "preprocess.max_points: must be >= preprocess.min_points"},
        Bad{"preprocess:\n  up_axis: x\n", "preprocess.up_axis: must be one of z, y, auto"},
        Bad{"preprocess:\n  f_d: 2\n", "preprocess.f_d: must be in (0, 1]"},
        Bad{"preprocess:\n  inside_vote: 1\n", "preprocess.inside_vote: must be in (0, 1)"},
        Bad{"preprocess:\n  min_points: 99999999999\n", "preprocess.min_points: integer out of range"},
        Bad{"preprocess:\n  f_d: 0.1\n  f_d: 0.2\n", "preprocess.f_d: duplicate key (test.yaml:3)"},
        Bad{"threads: -2\n", "threads: must be >= 0 (0 = all cores)"},
        Bad{"threads: [1]\n", "threads: expected a value, got a list"},
        Bad{"timeout_s: -1\n", "timeout_s: must be >= 0 (0 disables the deadline)"},
        Bad{"in_flight: 0\n", "in_flight: must be >= 1 or auto"},
        Bad{"lod: best\n", "lod: must be 'highest' or a CityJSON LoD such as 2.2, got 'best'"},
        Bad{"output_levels: [0.5]\n", "output_levels[0]: value is not one of decompose.levels"},
        Bad{"output_levels: [0.1, 0.1]\n", "output_levels[1]: duplicate level"},
        Bad{"output_levels: some\n", "output_levels: expected 'all' or a list"},
        Bad{"log_level: loud\n", "log_level: must be one of trace, debug, info"},
        Bad{"- 1\n- 2\n", "(root): expected a mapping of keys, got a list"},
        Bad{"preprocess: {cell_size: 1\n", "(yaml): invalid YAML"}));

TEST(ConfigError, CarriesKeyAndReason) {
  try {
    mc::load_config_string("decompose:\n  sigma: -1\n", "f.yaml");
    FAIL();
  } catch (const mc::ConfigError& e) {
    EXPECT_EQ(e.key(), "decompose.sigma");
    EXPECT_EQ(e.reason(), "must be >= 0, got -1");
  }
}

TEST(CheckConfig, RejectsProgrammaticValues) {
  mc::Params p;
  mc::RunConfig r;
  EXPECT_NO_THROW(mc::check_config(p, r));
  r.output_levels = {4};  // there are 4 levels: 0..3
  EXPECT_THROW(mc::check_config(p, r), mc::ConfigError);
  r.output_levels = {2, 1};
  EXPECT_THROW(mc::check_config(p, r), mc::ConfigError);
  r.output_levels = {};
  p.pre.max_distance = std::numeric_limits<double>::infinity();
  EXPECT_THROW(mc::check_config(p, r), mc::ConfigError);
}

}  // namespace
