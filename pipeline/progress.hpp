// A one-line progress bar on stderr: done/total, rate, ETA. Redrawn at most 10 times a second
// with '\r', so it costs nothing and does not flood a terminal; disabled entirely when stderr is
// not a terminal (logs and CI stay clean) or with --quiet.
#pragma once
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

namespace mc::pipeline {

class Progress {
 public:
  Progress(bool enabled, std::optional<size_t> total);
  ~Progress();
  void update(size_t done, size_t failed_or_partial);
  void finish();  // final redraw and newline

  // The line that would be drawn (for tests).
  static std::string render(size_t done, std::optional<size_t> total, size_t flagged, double seconds);

 private:
  bool enabled_;
  std::optional<size_t> total_;
  std::chrono::steady_clock::time_point start_, last_;
  size_t done_ = 0, flagged_ = 0;
  bool drawn_ = false;
  void draw();
};

// Whether stderr is a terminal.
bool stderr_is_tty();

}  // namespace mc::pipeline
