#include "pipeline/interrupt.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <optional>

#include "io/temp_registry.hpp"

namespace mc::pipeline {

namespace {
std::atomic<int> g_signal{0};
std::atomic<bool> g_installed{false};

void on_signal(int sig) {
  int expected = 0;
  if (!g_signal.compare_exchange_strong(expected, sig)) {
    // Second signal: the user means it. Temp files are gone already (io's handler ran first).
    mc::io::unlink_registered_temp_files();
    _exit(128 + sig);
  }
}
}  // namespace

void install_interrupt_handlers() {
  if (g_installed.exchange(true)) return;
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  for (int sig : {SIGINT, SIGTERM}) {
    struct sigaction old {};
    sigaction(sig, nullptr, &old);
    if (old.sa_handler == SIG_IGN) continue;  // e.g. nohup / background jobs: keep ignoring
    sigaction(sig, &sa, nullptr);
  }
  mc::io::install_temp_cleanup_signal_handlers();
}

int interrupt_signal() noexcept { return g_signal.load(); }
void request_interrupt(int sig) noexcept { g_signal.store(sig); }
void clear_interrupt() noexcept { g_signal.store(0); }

InterruptWatchdog::InterruptWatchdog(double grace_s) : grace_(grace_s), thread_([this] { loop(); }) {}

InterruptWatchdog::~InterruptWatchdog() {
  {
    std::lock_guard lock(m_);
    done_ = true;
  }
  cv_.notify_all();
  thread_.join();
}

void InterruptWatchdog::loop() {
  using Clock = std::chrono::steady_clock;
  std::unique_lock lock(m_);
  std::optional<Clock::time_point> since_signal;
  while (!done_) {
    cv_.wait_for(lock, std::chrono::milliseconds(50));
    if (done_) break;
    if (const int sig = interrupt_signal()) {
      if (!since_signal) since_signal = Clock::now();
      if (std::chrono::duration<double>(Clock::now() - *since_signal).count() > grace_) {
        mc::io::unlink_registered_temp_files();
        std::fprintf(stderr, "\nmorphcut-city: interrupted; buildings still running were abandoned\n");
        _exit(128 + sig);
      }
    }
  }
}

}  // namespace mc::pipeline
