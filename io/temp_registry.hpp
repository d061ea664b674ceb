// Process-wide registry of live temporary files, so that SIGINT/SIGTERM do not leave
// `<out>.tmp.<pid>` litter behind. Async-signal-safe by construction: a fixed array of slots
// holding C strings, each guarded by a lock-free atomic state; the handler only does atomic
// compare-exchange, unlink(2), sigaction(2) and raise(3).
#pragma once
#include <signal.h>

#include <cstddef>

namespace mc::io {

// Capacity of the registry; files beyond it are still written correctly, just not unlinked on
// a signal. Paths of TempRegistry::kMaxPath bytes or more are not registered either.
struct TempRegistry {
  static constexpr int kSlots = 128;
  static constexpr std::size_t kMaxPath = 4096;
};

// Registers an (absolute) path; returns the slot, or -1 when full or the path is too long.
int register_temp_file(const char* path) noexcept;
// Forgets a slot (no-op for -1, or when a signal handler already claimed it).
void unregister_temp_file(int slot) noexcept;
// Number of registered files (for tests and diagnostics).
int registered_temp_files() noexcept;
// Unlinks every registered file and forgets it. Async-signal-safe: usable from any handler.
void unlink_registered_temp_files() noexcept;

// Installs SIGINT and SIGTERM handlers that unlink the registered files and then carry on as
// before: a previously installed handler function is called; otherwise the default action
// (terminate, exit status 128+sig) is restored and the signal re-raised. A signal that was
// ignored when this is called stays ignored. Idempotent. Note: the files are unlinked before a
// chained handler runs, so an AtomicFile open at the signal can no longer commit() (it throws):
// a graceful stop must not expect to finish outputs that were being written.
void install_temp_cleanup_signal_handlers();

// From a signal handler: hands `sig` on to the handler that was installed before (`previous`),
// or, if that was the default action, restores it and re-raises the signal so the process ends
// as it would have. Async-signal-safe.
void chain_signal(const struct sigaction& previous, int sig, siginfo_t* info, void* context) noexcept;

}  // namespace mc::io
