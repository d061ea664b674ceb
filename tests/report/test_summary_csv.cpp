// The planners' CSV columns (report/summary_csv.hpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "report/summary_csv.hpp"

namespace {

using namespace mc::report;

TEST(Summary, ColumnsNameEveryWrittenLevel) {
  const auto c = summary_columns({0.1, 0.001});
  EXPECT_EQ(c[0], "id");
  EXPECT_NE(std::find(c.begin(), c.end(), "parts_0.1"), c.end());
  EXPECT_NE(std::find(c.begin(), c.end(), "parts_0.001"), c.end());
  for (const char* s :
       {"height", "footprint_area", "volume", "convexity", "mean_part_convexity", "largest_part_share",
        "max_degree", "end_parts", "centroid_x", "centroid_y", "centroid_z", "lon", "lat"})
    EXPECT_NE(std::find(c.begin(), c.end(), s), c.end()) << s;
}

}  // namespace
