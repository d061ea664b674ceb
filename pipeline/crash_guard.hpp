// Crash guard: a building that crashes the whole process (SIGSEGV, SIGBUS, SIGFPE, SIGILL,
// SIGABRT: a bug in a geometry library, a failed assertion) is not lost on the next run.
//
// The signal handler, on the thread that was running the building or one of its tasks (the
// thread tag, core/thread_tag.hpp), appends its id to the
// crash log (default OUTPUT.crashed, one "id<TAB>signal" line each), unlinks the atomic outputs'
// temp files, and then lets the signal take its usual course (a handler installed before ours,
// e.g. a sanitizer's, runs next; else the process dies by the signal). A later run with the same
// crash log writes every recorded building through unchanged with status "failed" and the
// reason, so the city completes. Deleting the log retries those buildings.
// Not covered: a stack overflow (no alternate signal stack on TBB threads), SIGKILL (OOM killer).
#pragma once
#include <array>
#include <cstddef>
#include <set>
#include <string>

#include "core/thread_tag.hpp"

namespace mc::pipeline {

class CrashGuard {
 public:
  // Reads the log if present and installs the handlers (once per process; the latest guard's
  // log is the one written). An empty path disables the guard.
  explicit CrashGuard(const std::string& log_path);
  ~CrashGuard();
  CrashGuard(const CrashGuard&) = delete;
  CrashGuard& operator=(const CrashGuard&) = delete;

  // Why `id` is skipped (it crashed an earlier run), or empty.
  std::string skip_reason(const std::string& id) const;
  size_t recorded() const { return crashed_.size(); }

  // Marks the calling thread, and the tasks its work hands to TBB (core/thread_tag.hpp), as
  // working on `id` for as long as it lives.
  class Scope {
   public:
    static constexpr size_t kMaxId = 1024;  // recorded ids are cut to kMaxId - 1 bytes
    explicit Scope(const std::string& id);
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    static std::array<char, kMaxId> make_id(const std::string& id);
    const std::array<char, kMaxId> id_;  // read by the crash handler through the thread tag
    const ThreadTagScope tag_;
  };

 private:
  std::string path_;
  std::set<std::string> crashed_;
};

}  // namespace mc::pipeline
