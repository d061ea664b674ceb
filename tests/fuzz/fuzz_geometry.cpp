// libFuzzer target: the geometric pipeline (preprocess + decompose + part meshes) on a tiny mesh
// decoded from the bytes, with small limits and a short deadline. Exceptions are how core reports
// unusable input (the pipeline turns them into a "failed" building); crashes, UB, hangs past the
// deadline and invalid part meshes are findings.
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <exception>

#include "core/decompose.hpp"
#include "core/preprocess.hpp"

namespace {

// Byte layout (missing bytes read as 0):
//   [0] vertex count 4 + b % 9 (<= 12)   [1] face count 1 + b % 12   [2] frame: scale and offset
//   then 3 bytes per vertex (signed, / 4: a 0.25 grid, so coplanar and coincident points are
//   common), then per face: a size byte (3 + b % 4 corners) and one index byte per corner.
mc::PolygonMesh decode(const uint8_t* data, size_t size) {
  size_t pos = 0;
  auto next = [&]() -> uint8_t { return pos < size ? data[pos++] : 0; };
  mc::PolygonMesh m;
  const size_t nv = 4 + next() % 9, nf = 1 + next() % 12;
  const uint8_t frame = next();
  static constexpr double kScale[] = {1.0, 0.01, 100.0, 1e-3};
  const double scale = kScale[frame % 4];
  // Real city coordinates (RD New metres) far from the origin: precision loss when centring.
  const mc::Vec3 offset = (frame / 4) % 2 ? mc::Vec3(85000, 446000, 0) : mc::Vec3(0, 0, 0);
  for (size_t i = 0; i < nv; ++i) {
    const double x = static_cast<int8_t>(next()) / 4.0, y = static_cast<int8_t>(next()) / 4.0,
                 z = static_cast<int8_t>(next()) / 4.0;
    m.vertices.push_back(mc::Vec3(x * scale, y * scale, z * scale) + offset);
  }
  const int32_t roof = m.label_index("RoofSurface");
  for (size_t f = 0; f < nf; ++f) {
    const uint8_t head = next();
    mc::Polygon poly;
    poly.rings.emplace_back();
    for (size_t k = 0; k < 3u + head % 4; ++k) poly.rings[0].push_back(next() % nv);
    poly.semantic = head & 0x80 ? roof : -1;
    m.faces.push_back(std::move(poly));
  }
  return m;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const mc::PolygonMesh mesh = decode(data, size);
  mc::Params p;
  p.pre.min_points = 10;
  p.pre.max_points = 100;
  p.pre.oracle_rays = 3;
  p.dec.levels = {0.1, 0.01};
  p.dec.node_budget = 200;
  p.dec.max_candidates = 6;
  p.dec.max_children = 8;
  const auto deadline = mc::Clock::now() + std::chrono::milliseconds(250);
  try {
    mc::Preprocessed pre = mc::preprocess(mesh, p.pre, deadline);
    const mc::PolygonMesh cell = mc::singleton_mesh(pre);
    for (const auto& face : cell.faces)
      for (uint32_t v : face.rings.at(0))
        if (v >= cell.vertices.size()) std::abort();
    const mc::Decomposition dec = mc::decompose(pre, p.dec, deadline);
    for (const auto& level : dec.levels)
      for (const auto& part : level.parts) {
        const mc::PolygonMesh pm = mc::part_mesh(pre, part);
        for (const auto& face : pm.faces)
          for (const auto& ring : face.rings)
            for (uint32_t v : ring)
              if (v >= pm.vertices.size()) std::abort();
      }
  } catch (const std::exception&) {}
  return 0;
}
