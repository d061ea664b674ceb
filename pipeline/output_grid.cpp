#include "pipeline/output_grid.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "io/cityjson_common.hpp"

namespace mc::pipeline {

namespace {

// `scale` divided by the smallest power of ten that brings it to `limit` or below, read back from
// its 15 significant digits (0.001 / 1e5 is 1e-08, not 1.0000000000000002e-08).
double refined(double scale, double limit) {
  double s = std::abs(scale);
  int k = 0;
  for (; k < 15 && s > limit * (1 + 1e-9); ++k) s /= 10;
  if (k == 0) return scale;
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", s);
  return std::copysign(std::strtod(text, nullptr), scale);
}

}  // namespace

OutputGrid refine_output_grid(mc::io::Header& h) {
  OutputGrid g;
  const mc::io::Transform t = mc::io::parse_transform(h.root, "header");
  g.present = t.present;
  if (!t.present) return g;
  g.input_scale = g.scale = t.scale;
  const CoordinateSystem& cs = h.coords;
  if (cs.geographic()) {
    g.scale.x = refined(t.scale.x, 1e-8);
    g.scale.y = refined(t.scale.y, 1e-8);
  }
  if (cs.kind != CoordinateSystem::Kind::Geocentric && cs.vertical_unit > 0)
    g.scale.z = refined(t.scale.z, 0.001 / cs.vertical_unit);
  g.refined = !(g.scale == t.scale);
  if (!g.refined) return g;
  h.root["transform"]["scale"] = {g.scale.x, g.scale.y, g.scale.z};
  std::ostringstream o;
  o << "output grid refined from the input's transform scale [" << t.scale.x << ", " << t.scale.y << ", "
    << t.scale.z << "] to [" << g.scale.x << ", " << g.scale.y << ", " << g.scale.z
    << "] (at most 1e-8 degrees and 1 mm of height): parts on a coarser grid fold; every input vertex "
       "keeps its coordinates";
  g.note = o.str();
  return g;
}

}  // namespace mc::pipeline
