// Shared by the fuzz targets. The readers take file paths (the CityJSON reader streams, the seq
// format is chosen by extension), so each input is written to one scratch file per process.
#pragma once
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/cityjson.hpp"

namespace mc::fuzz {

// A per-process path ending in `ext` in $TMPDIR (or /tmp); removed at normal exit.
inline std::string scratch_path(const std::string& ext) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/mc_fuzz_" + std::to_string(::getpid()) + ext;
}

inline std::string write_input(const uint8_t* data, size_t size, const std::string& ext) {
  static const std::string path = [&] {
    std::string p = scratch_path(ext);
    static std::string keep = p;
    std::atexit([] { std::remove(keep.c_str()); });
    return p;
  }();
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();  // the harness itself is broken, not the code under test
  if (size && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  return path;
}

// What the pipeline does with a file: read every feature, extract its building, write it back.
// ReadError is the documented file-level failure; anything else escaping is a finding.
inline void read_extract_write(const std::string& input, const std::string& output_ext) {
  try {
    mc::io::CityJsonReader reader(input);
    const mc::io::Header& header = reader.header();
    static const std::string output = scratch_path(".out" + output_ext);
    mc::io::CityJsonWriter writer(output, header);
    mc::io::Feature f;
    while (reader.next(f)) {
      mc::io::building_lods(f, header);
      mc::io::BuildingInput b = mc::io::extract_building(f, header);
      for (const auto& face : b.mesh.faces)
        for (const auto& ring : face.rings)
          for (uint32_t v : ring)
            if (v >= b.mesh.vertices.size()) std::abort();  // extraction must only hand out valid indices
      writer.write(f);
    }
    writer.close();
    std::remove(output.c_str());
  } catch (const mc::io::ReadError&) {}
}

}  // namespace mc::fuzz
