// The terrain height of a building's site from its attributes, when the file gives one: the
// ground level of a model without ground and walls (roofs only; docs/algorithm.md §6.4).
#pragma once
#include <cmath>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "io/cityjson_types.hpp"

namespace mc::pipeline {

// 3D BAG `h_maaiveld`, Rotterdam `TerrainHeight`, or an absolute minus a relative eaves height
// (`AbsoluteEavesHeight` - `RelativeEavesHeight`, as in DH_01_subs) of the top-level object;
// NaN when none is a finite number.
inline double terrain_height(const mc::io::Feature& f) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto o = f.objects.find(f.id);
  if (o == f.objects.end() || !o->is_object()) return nan;
  const auto a = o->find("attributes");
  if (a == o->end() || !a->is_object()) return nan;
  auto num = [&](const char* k) {
    const auto v = a->find(k);
    return v != a->end() && v->is_number() && std::isfinite(v->get<double>()) ? v->get<double>() : nan;
  };
  for (const char* k : {"h_maaiveld", "TerrainHeight"})
    if (const double v = num(k); std::isfinite(v)) return v;
  return num("AbsoluteEavesHeight") - num("RelativeEavesHeight");
}

}  // namespace mc::pipeline
