// Shared helpers of the CityGML reader tests: a whole read, the small files under
// tests/io/data/citygml, and a file's coordinates ring by ring.
#pragma once
#include <fstream>
#include <optional>

#include "io/citygml_reader.hpp"
#include "tests/io/io_test_util.hpp"

namespace mc::io::test {

struct GmlRead {
  Header header;
  std::vector<Feature> features;
  std::vector<std::string> problems;
  std::string format;
  std::map<std::string, size_t> skipped;
  std::optional<size_t> building_count;
};

inline GmlRead read_gml(const std::string& path) {
  CityGmlReader r(path);
  GmlRead out{r.header(), {}, {}, r.format(), {}, r.feature_count()};
  Feature f;
  while (r.next(f)) out.features.push_back(std::move(f));
  out.problems = r.problems();
  out.skipped = r.skipped_objects();
  return out;
}

// Tests that write small CityGML files into a scratch directory.
class GmlFileTest : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& xml) {
    const std::string p = dir_.file(name);
    std::ofstream(p) << xml;
    return p;
  }
  ScratchDir dir_;
};

// A small hand-written file of tests/io/data/citygml (its README says what each shows).
inline std::string gml_test_data(const std::string& name) {
  return std::string(MC_SOURCE_DIR) + "/tests/io/data/citygml/" + name;
}

// The coordinates of a ring (vertex indices into f.vertices), in order.
inline std::vector<Vec3> ring_points(const Feature& f, const nlohmann::json& ring) {
  std::vector<Vec3> out;
  for (const auto& i : ring) out.push_back(f.vertices.at(i.get<size_t>()));
  return out;
}

}  // namespace mc::io::test
