// SIGINT/SIGTERM: the first signal asks the run to stop (no new buildings are read, nothing more
// is written, outputs are not committed); a second one exits at once. Temp files of the atomic
// outputs are unlinked by io/'s handler, which runs first and chains to ours.
#pragma once

namespace mc::pipeline {

// Installs the handlers (ours, then io's temp-file cleanup in front of it). Idempotent.
void install_interrupt_handlers();
// The signal that asked us to stop, or 0.
int interrupt_signal() noexcept;
// For tests and for stopping a run programmatically.
void request_interrupt(int sig) noexcept;
void clear_interrupt() noexcept;

}  // namespace mc::pipeline
