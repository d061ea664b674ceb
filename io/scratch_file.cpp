#include "io/scratch_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "io/errors.hpp"

namespace mc::io {

namespace {
constexpr size_t kBuffer = 1 << 20;
}

ScratchFile::ScratchFile(const std::string& dir) {
  std::string d = dir;
  if (d.empty()) {
    const char* t = std::getenv("TMPDIR");
    d = (t && *t) ? t : "/tmp";
  }
  std::string tmpl = d + "/.mc_scratch_XXXXXX";
  fd_ = ::mkstemp(tmpl.data());
  if (fd_ < 0) throw WriteError("cannot create scratch file in " + d + ": " + std::strerror(errno));
  ::unlink(tmpl.c_str());
  buf_.reserve(kBuffer);
}

ScratchFile::~ScratchFile() {
  if (fd_ >= 0) ::close(fd_);
}

void ScratchFile::append(const void* data, size_t n) {
  const char* p = static_cast<const char*>(data);
  if (buf_.size() + n > kBuffer) flush();
  if (n >= kBuffer) {
    buf_.insert(buf_.end(), p, p + n);
    flush();
  } else {
    buf_.insert(buf_.end(), p, p + n);
  }
  size_ += n;
}

void ScratchFile::flush() {
  size_t done = 0;
  while (done < buf_.size()) {
    const ssize_t w = ::write(fd_, buf_.data() + done, buf_.size() - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      throw WriteError(std::string("scratch file write failed: ") + std::strerror(errno));
    }
    done += static_cast<size_t>(w);
  }
  buf_.clear();
}

void ScratchFile::read_at(uint64_t offset, void* out, size_t n) {
  if (!buf_.empty()) flush();
  char* p = static_cast<char*>(out);
  size_t done = 0;
  while (done < n) {
    const ssize_t r = ::pread(fd_, p + done, n - done, static_cast<off_t>(offset + done));
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) throw ReadError("scratch file read failed");
    done += static_cast<size_t>(r);
  }
}

}  // namespace mc::io
