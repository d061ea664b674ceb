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

// The written-out coefficients and the rounding by adding 1.5 · 2^52 give the very bits of the
// textbook form (divisions, std::nearbyint): the oracle's ray directions must not move.
TEST(FastSinCos, BitEqualToTheFormWithDivisionsAndNearbyint) {
  auto textbook = [](double x, double& sin_x, double& cos_x) {
    const auto& t = detail::sincos_table();
    volatile double six = 6, one20 = 120, five040 = 5040, two4 = 24, seven20 = 720, four0320 = 40320;
    const double step = 2 * M_PI / detail::SinCosTable::kSteps;
    const double jf = std::nearbyint(x / step);
    const int j = static_cast<int>(jf);
    const double r = std::fma(-jf, step, x);
    const double r2 = r * r;
    const double sr = r * (1 + r2 * (-1.0 / six + r2 * (1.0 / one20 + r2 * (-1.0 / five040))));
    const double cr = 1 + r2 * (-0.5 + r2 * (1.0 / two4 + r2 * (-1.0 / seven20 + r2 * (1.0 / four0320))));
    cos_x = t.c[j] * cr - t.s[j] * sr;
    sin_x = t.s[j] * cr + t.c[j] * sr;
  };
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI);
  for (int i = 0; i < 1000000; ++i) {
    // table points, half-steps (ties of the rounding) and random angles
    const double step = 2 * M_PI / detail::SinCosTable::kSteps;
    const double x = i <= 256 ? i * step : i <= 512 ? (i - 256.5) * step : angle(rng);
    if (x < 0) continue;
    double s1 = 0, c1 = 0, s2 = 0, c2 = 0;
    fast_sincos(x, s1, c1);
    textbook(x, s2, c2);
    ASSERT_EQ(s1, s2) << x;
    ASSERT_EQ(c1, c2) << x;
  }
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
