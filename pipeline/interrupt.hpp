// SIGINT/SIGTERM: the first signal asks the run to stop (no new buildings are read, nothing more
// is written, outputs are not committed); a second one exits at once. Temp files of the atomic
// outputs are unlinked by io/'s handler, which runs first and chains to ours.
#pragma once
#include <condition_variable>
#include <mutex>
#include <thread>

namespace mc::pipeline {

// Installs the handlers (ours, then io's temp-file cleanup in front of it). Idempotent.
void install_interrupt_handlers();
// The signal that asked us to stop, or 0.
int interrupt_signal() noexcept;
// For tests and for stopping a run programmatically.
void request_interrupt(int sig) noexcept;
void clear_interrupt() noexcept;

// After a signal, in-flight jobs cannot be cancelled (core only knows deadlines); the watchdog
// gives them `grace_s`, then leaves without outputs (temp files are unlinked first; exit code
// 128 + signal).
class InterruptWatchdog {
 public:
  explicit InterruptWatchdog(double grace_s);
  ~InterruptWatchdog();
  InterruptWatchdog(const InterruptWatchdog&) = delete;
  InterruptWatchdog& operator=(const InterruptWatchdog&) = delete;

 private:
  void loop();
  double grace_;
  std::mutex m_;
  std::condition_variable cv_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace mc::pipeline
