// Decomposes one building built in code with the installed morphcut::core library: an L-shaped
// block (10 x 8 m with a 6 x 4 m notch, 6 m high: 336 m³). Prints the parts per level; exits 0 when the
// singleton cell holds the block's volume and the finest level splits it into convex parts.
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/decompose.hpp"
#include "core/preprocess.hpp"

int main() {
  mc::PolygonMesh m;
  const std::vector<mc::Vec3> foot = {{0, 0, 0}, {10, 0, 0}, {10, 4, 0}, {4, 4, 0}, {4, 8, 0}, {0, 8, 0}};
  const double h = 6;
  const uint32_t n = static_cast<uint32_t>(foot.size());
  for (const auto& p : foot) m.vertices.push_back(p);
  for (const auto& p : foot) m.vertices.push_back({p.x, p.y, h});
  auto face = [&](std::vector<uint32_t> ring, const char* label) {
    mc::Polygon f;
    f.rings.push_back(std::move(ring));
    f.semantic = m.label_index(label);
    m.faces.push_back(std::move(f));
  };
  std::vector<uint32_t> floor, roof;
  for (uint32_t i = 0; i < n; ++i) floor.push_back(n - 1 - i), roof.push_back(n + i);
  face(floor, "GroundSurface");
  face(roof, "RoofSurface");
  for (uint32_t i = 0; i < n; ++i) face({i, (i + 1) % n, n + (i + 1) % n, n + i}, "WallSurface");

  mc::Params p;
  mc::Preprocessed pre =
      mc::preprocess(m, p.pre, mc::Clock::time_point::max(), std::numeric_limits<double>::quiet_NaN());
  double volume = 0;
  for (const auto& c : pre.components) volume += c.volume;
  const mc::Decomposition d = mc::decompose(pre, p.dec, mc::Clock::time_point::max());
  std::printf("singleton volume %.3f m3 (expected 336)\n", volume);
  for (const auto& level : d.levels)
    std::printf("level %g: %zu parts, convexity %.4f\n", level.lod, level.parts.size(), level.convexity);
  const bool ok = std::abs(volume - 336) < 1e-6 && !d.levels.empty() && d.levels.back().parts.size() >= 2 &&
                  d.levels.back().convexity > 0.99;
  return ok ? 0 : 1;
}
