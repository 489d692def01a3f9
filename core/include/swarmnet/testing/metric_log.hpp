// SDK test kit: what a fake context keeps of record() and sample() calls, checked as the kernel
// checks them, so a plugin's unit test sees the refusal a run would give.
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "swarmnet/units.hpp"

namespace swarmnet::testing {

// One sample() call: its time and value.
struct Sample {
  SimTime at;
  double value;
};

using RecordedMetrics = std::map<std::string, std::vector<double>, std::less<>>;
using SampledSeries = std::map<std::string, std::vector<Sample>, std::less<>>;

inline void log_record(RecordedMetrics& recorded, std::string_view metric, double value) {
  auto it = recorded.find(metric);
  if (it == recorded.end()) it = recorded.emplace(std::string(metric), std::vector<double>{}).first;
  it->second.push_back(value);
}

// Throws std::invalid_argument as the kernel does: an empty name or one with a line break, a
// value that is not finite.
inline void log_sample(SampledSeries& sampled, SimTime at, std::string_view series, double value) {
  if (series.empty() || series.find_first_of("\r\n") != std::string_view::npos) {
    throw std::invalid_argument("sample(): a series name must be one line, not empty");
  }
  if (!std::isfinite(value)) {
    throw std::invalid_argument("sample(\"" + std::string(series) + "\"): not a finite value");
  }
  auto it = sampled.find(series);
  if (it == sampled.end()) it = sampled.emplace(std::string(series), std::vector<Sample>{}).first;
  it->second.push_back(Sample{at, value});
}

}  // namespace swarmnet::testing
