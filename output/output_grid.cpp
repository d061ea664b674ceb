#include "output/output_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "io/cityjson_common.hpp"

namespace mc::output {

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
  // A linear grid is the user's choice (parts are made to fit it: docs/algorithm.md §7.4); a
  // grid of degrees set for other data (CityGML's millimetre default) is not.
  if (cs.geographic()) {
    g.scale.x = refined(t.scale.x, 1e-8);
    g.scale.y = refined(t.scale.y, 1e-8);
    if (cs.vertical_unit > 0) g.scale.z = refined(t.scale.z, 0.001 / cs.vertical_unit);
  }
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

double grid_step_metres(const mc::io::Transform& t, const WorkingFrame& frame, const Vec3& p) {
  if (!t.present) return 0;
  if (frame.identity()) return std::max({std::abs(t.scale.x), std::abs(t.scale.y), std::abs(t.scale.z)});
  const Vec3 m = frame.to_metric(p);
  double step = 0;
  for (const Vec3& d : {Vec3{t.scale.x, 0, 0}, Vec3{0, t.scale.y, 0}, Vec3{0, 0, t.scale.z}})
    step = std::max(step, norm(frame.to_metric(p + d) - m));
  return step;
}

}  // namespace mc::output
