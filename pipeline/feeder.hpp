// The source of a run's task graph (docs/design.md, "Largest buildings first"): features are read
// ahead of the writer, and the largest read is started first, so a large building does not start
// last and leave the other cores idle at the end. Outputs keep the input order (the graph's
// sequencer). When the buildings in flight are one short of the limiter's window, the lowest
// waiting sequence starts instead, so the building the writer waits for is always among those in
// flight (never a deadlock), and memory stays bounded by the window.
#pragma once
#include <atomic>
#include <exception>
#include <memory>
#include <vector>

#include "io/feature_source.hpp"
#include "report/outcome.hpp"

namespace mc::pipeline {

struct Work {
  size_t sequence = 0;
  bool largest_first = false;  // started ahead of its turn because it was the largest read
  double read_seconds = 0;
  mc::io::Feature feature;
  mc::report::BuildingOutcome outcome;
};
using Msg = std::shared_ptr<Work>;

class Feeder {
 public:
  // `window`: the buildings in flight (the limiter's size); at most threads - 1 run out of turn,
  // so the others keep the writer going.
  Feeder(mc::io::FeatureSource& reader, size_t window, int threads);

  // The next feature to start; null at the end of the input or on a read error (then error()).
  // Called from one thread at a time (the graph's input node).
  Msg next();
  std::exception_ptr error() const { return error_; }
  // The writer wrote one (before the limiter lets the next one in: next() counts on it).
  void written() { ++written_; }
  // A building started out of turn has finished, however its job ended.
  void out_of_turn_done() { --largest_running_; }

 private:
  mc::io::FeatureSource& reader_;
  const size_t window_, look_ahead_;
  const int max_largest_first_;
  std::vector<Msg> ahead_;  // read, not started
  size_t ahead_vertices_ = 0, next_sequence_ = 0, started_ = 0;
  bool input_done_ = false;
  std::atomic<size_t> written_{0};
  std::atomic<int> largest_running_{0};
  std::exception_ptr error_;
};

}  // namespace mc::pipeline
