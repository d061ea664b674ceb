// SHA-256 of a file, for the run report (which input exactly was processed). Self-contained
// (FIPS 180-4) so the build needs no crypto library; about 200-300 MB/s, and the run computes it
// on a side thread while the buildings are being processed.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace mc::io {

class Sha256 {
 public:
  Sha256();
  void update(const void* data, size_t n);
  std::string hex();  // finalises; call once

 private:
  void block(const unsigned char* p);
  uint32_t h_[8];
  unsigned char buf_[64];
  size_t used_ = 0;
  uint64_t bytes_ = 0;
};

std::string sha256_hex(std::string_view data);
// Throws std::runtime_error when the file cannot be read.
std::string sha256_file(const std::string& path);

}  // namespace mc::io
