// The tag of the work a thread does (the building a job decomposes), carried into the tasks that
// work spawns, so that a crash handler names the building whichever thread crashes
// (pipeline/crash_guard.cpp, docs/reliability.md). Reading it is async-signal-safe: a pointer to
// a NUL-terminated string owned by whoever set it, alive while it is set.
#pragma once
#include <utility>

namespace mc {

// This thread's tag, or nullptr.
const char* thread_tag();

// Sets this thread's tag for the scope's life; the previous one comes back after (a thread that
// helps another building's tasks while it waits nests scopes).
class ThreadTagScope {
 public:
  explicit ThreadTagScope(const char* tag);
  ~ThreadTagScope();
  ThreadTagScope(const ThreadTagScope&) = delete;
  ThreadTagScope& operator=(const ThreadTagScope&) = delete;

 private:
  const char* previous_;
};

// `f` wrapped to run under the calling thread's tag on whichever thread runs it: every task body
// a building's work hands to TBB goes through it.
template <class F>
auto with_thread_tag(F f) {
  return [tag = thread_tag(), f = std::move(f)](auto&&... args) -> decltype(auto) {
    const ThreadTagScope scope(tag);
    return f(std::forward<decltype(args)>(args)...);
  };
}

}  // namespace mc
