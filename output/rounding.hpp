// Values written to the output files are rounded to a fixed step: the last bits of a hull volume,
// or of a vertex computed from a lazily evaluated exact plane, depend on the order in which exact
// evaluations happened, not on the building, and the written files must be byte-identical
// (docs/output-format.md). The steps (1e-6 m³ for a volume, 1e-9 for a ratio) are far below any
// meaning.
#pragma once
#include <cmath>

namespace mc::output {

inline double rounded(double v, double step) { return std::isfinite(v) ? std::round(v / step) * step : v; }

}  // namespace mc::output
