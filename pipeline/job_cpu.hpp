// CPU time: the process's, a thread's, and a building's job over every thread that works for it
// (docs/design.md, "Largest buildings first"; the city benchmark's parallel efficiency).
#pragma once
#include <pthread.h>
#include <sys/resource.h>
#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#include <algorithm>
#include <ctime>
#include <mutex>
#include <vector>

namespace mc::pipeline {

// CPU seconds of a thread so far (`clock`: its CPU-time clock).
inline double cpu_seconds_of(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

// CPU seconds of the calling thread so far.
inline double thread_cpu_seconds() { return cpu_seconds_of(CLOCK_THREAD_CPUTIME_ID); }

// User + system CPU seconds of the whole process so far (every thread).
// The process's peak resident memory in MB (Linux reports kilobytes).
inline double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

inline double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

// The CPU seconds that worker threads spend in one arena, each from entering it to leaving it.
// The thread that runs the arena's work (`execute`) is not counted: it measures its own time. A
// worker can stay in the arena a while after the work is done, so `close()` reads the clocks of
// those still in it (a thread's CPU clock can be read from another thread) and counts nothing
// after that.
class ArenaWorkerCpu : public tbb::task_scheduler_observer {
 public:
  explicit ArenaWorkerCpu(tbb::task_arena& arena) : tbb::task_scheduler_observer(arena) { observe(true); }
  ~ArenaWorkerCpu() override { observe(false); }
  ArenaWorkerCpu(const ArenaWorkerCpu&) = delete;
  ArenaWorkerCpu& operator=(const ArenaWorkerCpu&) = delete;

  void on_scheduler_entry(bool worker) override {
    if (!worker) return;
    const clockid_t clock = this_thread_clock();
    std::lock_guard<std::mutex> lock(m_);
    if (!closed_) inside_.push_back({clock, cpu_seconds_of(clock)});
  }
  void on_scheduler_exit(bool worker) override {
    if (!worker) return;
    const clockid_t clock = this_thread_clock();
    std::lock_guard<std::mutex> lock(m_);
    auto it = std::find_if(inside_.begin(), inside_.end(), [&](const Inside& w) { return w.clock == clock; });
    if (it == inside_.end()) return;
    seconds_ += cpu_seconds_of(clock) - it->entered;
    inside_.erase(it);
  }
  // The workers' CPU seconds in the arena up to now.
  double close() {
    std::lock_guard<std::mutex> lock(m_);
    for (const Inside& w : inside_) seconds_ += cpu_seconds_of(w.clock) - w.entered;
    inside_.clear();
    closed_ = true;
    return seconds_;
  }

 private:
  static clockid_t this_thread_clock() {
    clockid_t clock = CLOCK_THREAD_CPUTIME_ID;
    pthread_getcpuclockid(pthread_self(), &clock);
    return clock;
  }
  struct Inside {
    clockid_t clock;
    double entered;
  };
  std::mutex m_;
  std::vector<Inside> inside_;
  double seconds_ = 0;
  bool closed_ = false;
};

}  // namespace mc::pipeline
