// fast_sincos against libm: within a few ulp everywhere on [0, 2π], and equal once rounded to
// float (what Embree receives) on all but a handful of a million angles.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/fast_sincos.hpp"

namespace mc {
namespace {

TEST(FastSinCos, WithinAFewUlpOfLibmOnTheWholeCircle) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  double worst = 0;
  int float_differs = 0;
  const int n = 1000000;
  for (int i = 0; i < n; ++i) {
    const double x = i < 1025 ? 2 * M_PI * i / 1024 : angle(rng);  // table points and the ends too
    double s = 0, c = 0;
    fast_sincos(x, s, c);
    worst = std::max({worst, std::abs(s - std::sin(x)), std::abs(c - std::cos(x))});
    float_differs += static_cast<float>(s) != static_cast<float>(std::sin(x)) ||
                     static_cast<float>(c) != static_cast<float>(std::cos(x));
  }
  EXPECT_LE(worst, 1e-15);
  EXPECT_LE(float_differs, 5);
}

TEST(FastSinCos, ExactAtTheQuarterTurns) {
  double s = 1, c = 0;
  fast_sincos(0, s, c);
  EXPECT_EQ(s, 0);
  EXPECT_EQ(c, 1);
  fast_sincos(M_PI / 2, s, c);
  EXPECT_NEAR(c, 0, 1e-16);
  EXPECT_EQ(s, 1);
}

}  // namespace
}  // namespace mc
