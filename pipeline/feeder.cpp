#include "pipeline/feeder.hpp"

#include <algorithm>
#include <chrono>

namespace mc::pipeline {

namespace {
// Features read ahead of the writer, among which the largest is started first (at least the
// in-flight window).
constexpr size_t kLookAhead = 256;
// and at most this many vertices among them beyond the window (a parsed feature takes about
// 0.75 kB per vertex: this bounds the look-ahead's memory at about 25 MB whatever the buildings).
constexpr size_t kLookAheadVertices = 32768;
}  // namespace

// The source looks further ahead than the window, so a large building starts long before the
// writer needs it (not when it enters the window, where the window could fill up with small
// buildings finished behind it and leave cores idle).
Feeder::Feeder(mc::io::FeatureSource& reader, size_t window, int threads)
    : reader_(reader),
      window_(window),
      look_ahead_(std::max(window, kLookAhead)),
      max_largest_first_(std::max(1, threads - 1)) {}

Msg Feeder::next() {
  while (!input_done_ &&
         (ahead_.size() < window_ || (ahead_.size() < look_ahead_ && ahead_vertices_ < kLookAheadVertices))) {
    auto w = std::make_shared<Work>();
    const auto t = std::chrono::steady_clock::now();
    try {
      if (!reader_.next(w->feature)) {
        input_done_ = true;
        break;
      }
    } catch (...) {
      error_ = std::current_exception();
      return {};
    }
    w->read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    w->sequence = next_sequence_++;
    ahead_vertices_ += w->feature.vertices.size();
    ahead_.push_back(std::move(w));
  }
  if (ahead_.empty()) return {};
  auto lowest = [](const Msg& a, const Msg& b) { return a->sequence < b->sequence; };
  auto pick = std::min_element(ahead_.begin(), ahead_.end(), lowest);
  const bool largest =
      started_ - written_.load() + 1 < window_ && largest_running_.load() < max_largest_first_;
  if (largest) {
    pick = std::min_element(ahead_.begin(), ahead_.end(), [](const Msg& a, const Msg& b) {
      const size_t na = a->feature.vertices.size(), nb = b->feature.vertices.size();
      return na != nb ? na > nb : a->sequence < b->sequence;
    });
    (*pick)->largest_first = true;
    ++largest_running_;
  }
  Msg w = std::move(*pick);
  ahead_.erase(pick);
  ahead_vertices_ -= w->feature.vertices.size();
  ++started_;
  return w;
}

}  // namespace mc::pipeline
