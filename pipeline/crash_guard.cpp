#include "pipeline/crash_guard.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <mutex>

#include "core/thread_tag.hpp"
#include "io/temp_registry.hpp"

namespace mc::pipeline {

namespace {

constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
constexpr size_t kMaxId = CrashGuard::Scope::kMaxId, kMaxPath = 4096;

// Read by the handler: plain storage only (no allocation, no locks).
char g_log[kMaxPath];  // empty = guard off
struct sigaction g_previous[std::size(kSignals)];
// The building a crashing thread works on is its thread tag (core/thread_tag.hpp): set by the
// job's Scope and carried into every task the job's work hands to TBB, so a crash on a thread
// that helps the job names it too.
thread_local bool t_recorded = false;

void write_all(int fd, const char* s, size_t n) {
  while (n > 0) {
    const ssize_t k = ::write(fd, s, n);
    if (k <= 0) return;
    s += k;
    n -= static_cast<size_t>(k);
  }
}

void on_crash(int sig, siginfo_t* info, void* context) {
  mc::io::unlink_registered_temp_files();
  const char* id = mc::thread_tag();
  if (g_log[0] && id && id[0] && !t_recorded) {
    const int fd = ::open(g_log, O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (fd >= 0) {
      char line[kMaxId + 16];
      size_t n = std::strlen(id);
      std::memcpy(line, id, n);
      line[n++] = '\t';
      char digits[8];
      int d = 0;
      for (int s = sig; s > 0 && d < 8; s /= 10) digits[d++] = static_cast<char>('0' + s % 10);
      while (d > 0) line[n++] = digits[--d];
      line[n++] = '\n';
      write_all(fd, line, n);
      ::close(fd);
    }
    t_recorded = true;  // a second fault on this thread records nothing more
  }
  size_t i = 0;
  while (i + 1 < std::size(kSignals) && kSignals[i] != sig) ++i;
  mc::io::chain_signal(g_previous[i], sig, info, context);
}

void install_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (size_t i = 0; i < std::size(kSignals); ++i) {
      sigaction(kSignals[i], nullptr, &g_previous[i]);
      struct sigaction sa {};
      sa.sa_sigaction = on_crash;
      sa.sa_flags = SA_SIGINFO;
      sigemptyset(&sa.sa_mask);
      sigaction(kSignals[i], &sa, nullptr);
    }
  });
}

// The form an id is recorded in: at most kMaxId - 1 bytes, no line breaks or tabs.
std::string recorded_form(const std::string& id) {
  std::string r = id.substr(0, kMaxId - 1);
  for (char& c : r)
    if (c == '\n' || c == '\t' || c == '\r') c = ' ';
  return r;
}

}  // namespace

CrashGuard::CrashGuard(const std::string& log_path) : path_(log_path) {
  if (path_.empty() || path_.size() >= kMaxPath) return;
  std::ifstream in(path_);
  for (std::string line; std::getline(in, line);) {
    const size_t tab = line.find('\t');
    const std::string id = line.substr(0, tab);
    if (!id.empty()) crashed_.insert(id);
  }
  std::memcpy(g_log, path_.c_str(), path_.size() + 1);
  install_once();
}

CrashGuard::~CrashGuard() {
  if (!path_.empty()) g_log[0] = '\0';
}

std::string CrashGuard::skip_reason(const std::string& id) const {
  if (!crashed_.count(recorded_form(id))) return {};
  return "this building crashed an earlier run (recorded in " + path_ +
         "); written through unchanged. Delete that file to try it again";
}

CrashGuard::Scope::Scope(const std::string& id) : id_(make_id(id)), tag_(id_.data()) {}

std::array<char, CrashGuard::Scope::kMaxId> CrashGuard::Scope::make_id(const std::string& id) {
  const std::string r = recorded_form(id);
  std::array<char, kMaxId> out{};
  std::memcpy(out.data(), r.data(), r.size());
  return out;
}

}  // namespace mc::pipeline
