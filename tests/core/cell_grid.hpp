// A complex cut into a grid of unit cells: the box [0, n]³ split by the planes x, y, z = 1 … n − 1.
// Tests of carving (cavities) and of part analysis (pinches, genus) select cells from it.
#pragma once
#include "core/complex.hpp"

namespace mc::test {

inline void split_into_unit_cells(CellComplex& cx, PlaneRegistry& reg, int n) {
  for (int axis = 0; axis < 3; ++axis)
    for (int at = 1; at < n; ++at) {
      Vec3 normal{0, 0, 0};
      (axis == 0 ? normal.x : axis == 1 ? normal.y : normal.z) = 1;
      const uint32_t p = reg.add({normal, -static_cast<double>(at)});
      for (uint32_t c : cx.live_cells()) cx.split(c, p);
    }
}

}  // namespace mc::test
