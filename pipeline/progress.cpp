#include "pipeline/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace mc::pipeline {

namespace {
std::string clock_text(double s) {
  if (!std::isfinite(s) || s < 0) return "--:--";
  const long t = std::lround(s);
  char buf[32];
  if (t >= 3600) std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
  else std::snprintf(buf, sizeof buf, "%ld:%02ld", t / 60, t % 60);
  return buf;
}
}  // namespace

bool stderr_is_tty() { return isatty(STDERR_FILENO) == 1; }

Progress::Progress(bool enabled, std::optional<size_t> total)
    : enabled_(enabled), total_(total), start_(std::chrono::steady_clock::now()), last_(start_) {}

Progress::~Progress() { finish(); }

std::string Progress::render(size_t done, std::optional<size_t> total, size_t flagged, double seconds) {
  const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0;
  char buf[256];
  std::string bar;
  if (total && *total > 0) {
    constexpr int kWidth = 24;
    const double f = std::min(1.0, static_cast<double>(done) / static_cast<double>(*total));
    const int filled = static_cast<int>(f * kWidth);
    bar = "[" + std::string(filled, '#') + std::string(kWidth - filled, '.') + "] ";
    const double eta = rate > 0 ? static_cast<double>(*total - std::min(done, *total)) / rate : NAN;
    std::snprintf(buf, sizeof buf, "%zu/%zu features  %.1f/s  ETA %s", done, *total, rate,
                  clock_text(eta).c_str());
  } else {
    std::snprintf(buf, sizeof buf, "%zu features  %.1f/s  elapsed %s", done, rate,
                  clock_text(seconds).c_str());
  }
  std::string line = bar + buf;
  if (flagged) line += "  (" + std::to_string(flagged) + " not ok)";
  return line;
}

void Progress::draw() {
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::fprintf(stderr, "\r%s\033[K", render(done_, total_, flagged_, s).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::update(size_t done, size_t flagged) {
  if (!enabled_) return;
  done_ = done, flagged_ = flagged;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  draw();
}

void Progress::finish() {
  if (!enabled_) return;
  draw();
  std::fputc('\n', stderr);
  enabled_ = false;
}

}  // namespace mc::pipeline
