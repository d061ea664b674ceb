// sin and cos of one angle from a 256-entry table and short Taylor series: within 3 ulp of the
// libm values (measured maximum error 5.6e-16) at a fifth of their cost. The oracle's ray
// directions use it; they go to Embree in float, where the two agree on all but about one
// direction in 20 million (docs/algorithm.md §6.1).
#pragma once
#include <array>
#include <cmath>

namespace mc {

namespace detail {
struct SinCosTable {
  static constexpr int kSteps = 256;
  std::array<double, kSteps + 1> c, s;
  SinCosTable() {
    for (int j = 0; j <= kSteps; ++j) {
      c[j] = std::cos(2 * M_PI * j / kSteps);
      s[j] = std::sin(2 * M_PI * j / kSteps);
    }
  }
};
inline const SinCosTable& sincos_table() {
  static const SinCosTable t;
  return t;
}
}  // namespace detail

// The Taylor coefficients as the doubles nearest to ±1/n!, written out: CGAL's -frounding-math
// keeps the compiler from folding 1.0 / 6 and the like, so written as quotients they cost six
// divisions per call.
namespace detail {
constexpr double kInv3f = -0x1.5555555555555p-3;   // -1/3!
constexpr double kInv5f = 0x1.1111111111111p-7;    // 1/5!
constexpr double kInv7f = -0x1.a01a01a01a01ap-13;  // -1/7!
constexpr double kInv4f = 0x1.5555555555555p-5;    // 1/4!
constexpr double kInv6f = -0x1.6c16c16c16c17p-10;  // -1/6!
constexpr double kInv8f = 0x1.a01a01a01a01ap-16;   // 1/8!
// v rounded to the nearest integer, ties to even (std::nearbyint in the default rounding mode, a
// library call without SSE4.1), for 0 <= v < 2^51: adding 1.5 · 2^52 leaves no fraction bits.
inline double round_to_integer(double v) {
  constexpr double kShift = 0x1.8p52;
  return (v + kShift) - kShift;
}
}  // namespace detail

// x in [0, 2π] (the table's range; the ray directions' azimuths).
inline void fast_sincos(double x, double& sin_x, double& cos_x) {
  using namespace detail;
  const auto& t = sincos_table();
  constexpr double step = 2 * M_PI / SinCosTable::kSteps;
  const double jf = round_to_integer(x / step);
  const int j = static_cast<int>(jf);
  const double r = std::fma(-jf, step, x);  // |r| <= step / 2: the Taylor terms below suffice
  const double r2 = r * r;
  const double sr = r * (1 + r2 * (kInv3f + r2 * (kInv5f + r2 * kInv7f)));
  const double cr = 1 + r2 * (-0.5 + r2 * (kInv4f + r2 * (kInv6f + r2 * kInv8f)));
  cos_x = t.c[j] * cr - t.s[j] * sr;
  sin_x = t.s[j] * cr + t.c[j] * sr;
}

}  // namespace mc
