#include "io/temp_registry.hpp"

#include <sched.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>
#include <mutex>

namespace mc::io {
namespace {

static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

// A slot returns to kFree only through its owner, so a handler never frees a slot that the owner
// then "unregisters" after someone else reused it. kClaimed: a handler is unlinking the path.
enum State : int { kFree = 0, kFilling = 1, kLive = 2, kClaimed = 3, kUnlinked = 4 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[TempRegistry::kMaxPath];
};

Slot g_slots[TempRegistry::kSlots];

constexpr int kSignals[] = {SIGINT, SIGTERM};
struct sigaction g_previous[2];

void on_signal(int sig, siginfo_t* info, void* context) {
  unlink_registered_temp_files();
  const int i = sig == SIGINT ? 0 : 1;
  chain_signal(g_previous[i], sig, info, context);
}

}  // namespace

void chain_signal(const struct sigaction& prev, int sig, siginfo_t* info, void* context) noexcept {
  if (prev.sa_flags & SA_SIGINFO) {
    if (prev.sa_sigaction) prev.sa_sigaction(sig, info, context);
    return;
  }
  if (prev.sa_handler != SIG_DFL && prev.sa_handler != SIG_IGN) {
    prev.sa_handler(sig);
    return;
  }
  // Default action: die by the same signal so the parent sees the usual status. The signal is
  // blocked while we run, so the re-raised one is delivered as soon as the handler returns.
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  sigaction(sig, &dfl, nullptr);
  raise(sig);
}

int register_temp_file(const char* path) noexcept {
  const std::size_t n = std::strlen(path);
  if (n >= TempRegistry::kMaxPath) return -1;
  for (int i = 0; i < TempRegistry::kSlots; ++i) {
    int expected = kFree;
    if (g_slots[i].state.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) {
      std::memcpy(g_slots[i].path, path, n + 1);
      g_slots[i].state.store(kLive, std::memory_order_release);
      return i;
    }
  }
  return -1;
}

void unregister_temp_file(int slot) noexcept {
  if (slot < 0 || slot >= TempRegistry::kSlots) return;
  std::atomic<int>& state = g_slots[slot].state;
  for (;;) {
    int expected = kLive;
    if (state.compare_exchange_strong(expected, kFree, std::memory_order_acq_rel)) return;
    if (expected == kUnlinked) {
      state.store(kFree, std::memory_order_release);
      return;
    }
    if (expected != kClaimed) return;  // not registered: nothing to do
    // A handler on another thread is unlinking this path right now; it finishes quickly.
    sched_yield();
  }
}

int registered_temp_files() noexcept {
  int n = 0;
  for (const Slot& s : g_slots) n += s.state.load(std::memory_order_acquire) == kLive;
  return n;
}

void unlink_registered_temp_files() noexcept {
  for (Slot& s : g_slots) {
    int expected = kLive;
    // Claiming first means no thread can reuse the slot while we read its path.
    if (s.state.compare_exchange_strong(expected, kClaimed, std::memory_order_acq_rel)) {
      ::unlink(s.path);
      s.state.store(kUnlinked, std::memory_order_release);
    }
  }
}

void install_temp_cleanup_signal_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int i = 0; i < 2; ++i) {
      struct sigaction current {};
      sigaction(kSignals[i], nullptr, &current);
      if (!(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_IGN) continue;
      g_previous[i] = current;
      struct sigaction sa {};
      sa.sa_sigaction = on_signal;
      sa.sa_flags = SA_SIGINFO | SA_RESTART;
      sigemptyset(&sa.sa_mask);
      for (int s : kSignals) sigaddset(&sa.sa_mask, s);  // one cleanup at a time
      sigaction(kSignals[i], &sa, nullptr);
    }
  });
}

}  // namespace mc::io
