// An anonymous scratch file (created then unlinked at once, so it vanishes even on a crash) with
// buffered appends and positional reads. Used to keep city-sized arrays (the vertex list) out of
// memory: the page cache holds them, not the process.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mc::io {

class ScratchFile {
 public:
  // `dir` empty = $TMPDIR or /tmp. Throws WriteError when no file can be created.
  explicit ScratchFile(const std::string& dir = "");
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  void append(const void* data, size_t n);
  void append(const std::string& s) { append(s.data(), s.size()); }
  void flush();
  uint64_t size() const { return size_; }
  // Reads n bytes at `offset` (flushes pending appends first).
  void read_at(uint64_t offset, void* out, size_t n);

 private:
  int fd_ = -1;
  uint64_t size_ = 0;
  std::vector<char> buf_;
};

}  // namespace mc::io
