// Shared helpers of the io/ tests: data locations, a scratch directory, whole-file reads.
#pragma once
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "io/cityjson.hpp"

namespace mc::io::test {

namespace fs = std::filesystem;

inline std::string project_data(const std::string& rel) {
  return std::string(MC_SOURCE_DIR) + "/datasets/" + rel;
}
inline std::string bad_input(const std::string& name) {
  return std::string(MC_SOURCE_DIR) + "/tests/io/bad/" + name;
}
// The shared read-only data beside the repository (CI: ../shared).
inline std::string shared_dir() { return std::string(MC_SOURCE_DIR) + "/../shared/datasets"; }
inline bool have_shared() { return fs::is_directory(shared_dir() + "/cityjson"); }

// A fresh directory under the build tree, removed at the end of the test.
class ScratchDir {
 public:
  ScratchDir() {
    static int n = 0;
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::path(MC_BINARY_DIR) / "io_test_tmp" /
            (std::string(info ? info->name() : "x") + "_" + std::to_string(::getpid()) + "_" +
             std::to_string(n++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~ScratchDir() { fs::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  size_t entries() const {
    return static_cast<size_t>(std::distance(fs::directory_iterator(path_), fs::directory_iterator()));
  }

 private:
  fs::path path_;
};

struct WholeRead {
  Header header;
  std::vector<Feature> features;
  std::vector<std::string> problems;
};
inline WholeRead read_all(const std::string& path) {
  CityJsonReader r(path);
  WholeRead out{r.header(), {}, {}};
  Feature f;
  while (r.next(f)) out.features.push_back(std::move(f));
  out.problems = r.problems();
  return out;
}

inline bool contains(const std::vector<std::string>& list, const std::string& text) {
  for (const auto& s : list)
    if (s == text) return true;
  return false;
}
inline std::string joined(const std::vector<std::string>& list) {
  std::string s;
  for (const auto& e : list) s += "  | " + e + "\n";
  return s;
}

// The ReadError message of opening `path`, or "" when it opens.
inline std::string open_error(const std::string& path) {
  try {
    CityJsonReader r(path);
    Feature f;
    while (r.next(f)) {}
  } catch (const ReadError& e) { return e.what(); }
  return "";
}

}  // namespace mc::io::test
