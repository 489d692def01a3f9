// A one-line progress display on a terminal (step, simulated time, real-time factor), for runs
// longer than a second. Silent when the stream is not a terminal, so logs and pipes stay clean.
// Reads the wall clock for display only.
#pragma once

#include <chrono>
#include <cstdint>
#include <cstdio>

namespace swarmnet {

class ProgressLine {
 public:
  ProgressLine(std::FILE* terminal, std::uint64_t total_steps, double step_s);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  ProgressLine(ProgressLine&&) = delete;
  ProgressLine& operator=(ProgressLine&&) = delete;

  // Cheap when nothing is shown: checks the clock every 64 steps.
  void update(std::uint64_t step);
  // Erases the line.
  void clear();

 private:
  std::FILE* out_;
  bool enabled_;
  bool shown_ = false;
  std::uint64_t total_steps_;
  double step_s_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace swarmnet
