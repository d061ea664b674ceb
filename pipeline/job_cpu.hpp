// The CPU time a building's job takes, over every thread that works for it
// (docs/design.md, "Largest buildings first"; the city benchmark's parallel efficiency).
#pragma once
#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#include <atomic>
#include <ctime>

namespace mc::pipeline {

// CPU seconds of the calling thread so far.
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

// The CPU seconds that worker threads spend in one arena, each from entering it to leaving it.
// The thread that runs the arena's work (`execute`) is not counted: it measures its own time.
class ArenaWorkerCpu : public tbb::task_scheduler_observer {
 public:
  explicit ArenaWorkerCpu(tbb::task_arena& arena) : tbb::task_scheduler_observer(arena) { observe(true); }
  ~ArenaWorkerCpu() override { observe(false); }
  ArenaWorkerCpu(const ArenaWorkerCpu&) = delete;
  ArenaWorkerCpu& operator=(const ArenaWorkerCpu&) = delete;
  void on_scheduler_entry(bool worker) override {
    if (worker) entered_ = thread_cpu_seconds();
  }
  void on_scheduler_exit(bool worker) override {
    if (worker) seconds_.fetch_add(thread_cpu_seconds() - entered_);
  }
  double seconds() const { return seconds_.load(); }

 private:
  static inline thread_local double entered_ = 0;  // a worker is in one observed arena at a time
  std::atomic<double> seconds_{0};
};

}  // namespace mc::pipeline
