// Output files that appear complete or not at all: write to `<path>.tmp.<pid>` in the same
// directory, then rename over `path` on commit(). Re-runs and readers never see a half-written
// report, and an interrupted run leaves the previous output intact. The temp file is removed
// when the object dies without commit() (exceptions), and on SIGINT/SIGTERM once
// install_temp_cleanup_signal_handlers() has been called.
#pragma once
#include <fstream>
#include <ostream>
#include <string>

#include "io/temp_registry.hpp"

namespace mc::io {

class AtomicFile {
 public:
  // Creates the temp file; throws std::system_error if it cannot, std::logic_error if this
  // process is already writing `path` through another AtomicFile.
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }

  // Flushes, fsyncs and renames the temp file over `path` (then fsyncs the directory so the
  // rename survives a crash). Throws std::system_error on any failure (disk full included);
  // the temp file is then removed by the destructor and `path` is untouched.
  void commit();

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_path_; }
  bool committed() const { return committed_; }
  // False if the signal registry was full (the file is still written correctly).
  bool signal_protected() const { return slot_ >= 0; }

 private:
  void release_name();

  std::string path_;
  std::string temp_path_;
  std::ofstream out_;
  int slot_ = -1;
  bool committed_ = false;
};

}  // namespace mc::io
