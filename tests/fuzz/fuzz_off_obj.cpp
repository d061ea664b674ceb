// libFuzzer target: the OFF and OBJ readers. The first byte picks the format (even = OFF).
#include "fuzz_util.hpp"
#include "io/off_obj.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const bool off = data[0] % 2 == 0;
  const std::string path = mc::fuzz::write_input(data + 1, size - 1, off ? ".off" : ".obj");
  try {
    std::vector<std::string> problems;
    const mc::PolygonMesh m = off ? mc::io::read_off(path, &problems) : mc::io::read_obj(path, &problems);
    for (const auto& face : m.faces) {
      if (face.rings.empty() || face.rings[0].size() < 3) std::abort();  // documented: such faces are skipped
      for (const auto& ring : face.rings)
        for (uint32_t v : ring)
          if (v >= m.vertices.size()) std::abort();
      if (face.semantic >= static_cast<int32_t>(m.semantic_labels.size())) std::abort();
    }
    for (const auto& face : m.faces) mc::io::bridge_holes(m, face);
  } catch (const mc::io::ReadError&) {}
  return 0;
}
