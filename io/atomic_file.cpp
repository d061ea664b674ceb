#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>
#include <system_error>

namespace mc::io {
namespace {

// Temp names are per process, so two writers of one path in this process would collide.
std::mutex g_names_mutex;
std::set<std::string> g_names;

[[noreturn]] void throw_errno(int err, const std::string& what) {
  throw std::system_error(err, std::generic_category(), what);
}

void fsync_path(const std::string& p, int flags, bool required) {
  const int fd = ::open(p.c_str(), flags | O_CLOEXEC);
  if (fd < 0) {
    if (required) throw_errno(errno, "cannot open " + p + " to sync it");
    return;
  }
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0 && required) throw_errno(err, "cannot sync " + p);
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  namespace fs = std::filesystem;
  // Absolute, so the signal handler unlinks the right file even after a chdir.
  temp_path_ = fs::absolute(fs::path(path_)).string() + ".tmp." + std::to_string(::getpid());
  {
    std::lock_guard lock(g_names_mutex);
    if (!g_names.insert(temp_path_).second)
      throw std::logic_error("AtomicFile: " + path_ + " is already being written by this process");
  }
  // Register before creating, so there is no window where the file exists unregistered.
  slot_ = register_temp_file(temp_path_.c_str());
  out_.open(temp_path_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    const int err = errno;
    release_name();
    throw_errno(err, "cannot create " + temp_path_);
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(temp_path_.c_str());
  }
  release_name();
}

void AtomicFile::release_name() {
  unregister_temp_file(slot_);
  slot_ = -1;
  std::lock_guard lock(g_names_mutex);
  g_names.erase(temp_path_);
}

void AtomicFile::commit() {
  if (committed_) throw std::logic_error("AtomicFile: commit() called twice for " + path_);
  out_.flush();
  if (!out_) throw_errno(errno ? errno : EIO, "cannot write " + temp_path_);
  out_.close();
  if (out_.fail()) throw_errno(errno ? errno : EIO, "cannot close " + temp_path_);
  fsync_path(temp_path_, O_RDONLY, true);
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0)
    throw_errno(errno, "cannot rename " + temp_path_ + " to " + path_);
  committed_ = true;
  release_name();
  // Best effort: some file systems refuse fsync on directories.
  const std::filesystem::path dir = std::filesystem::absolute(path_).parent_path();
  fsync_path(dir.string(), O_RDONLY | O_DIRECTORY, false);
}

}  // namespace mc::io
