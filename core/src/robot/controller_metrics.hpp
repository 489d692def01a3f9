// Metrics that controllers record through RobotContext::record(), summed over all robots.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <string_view>

namespace swarmnet {

struct MetricSummary {
  std::uint64_t count = 0;
  double sum = 0.0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();

  void add(double value) {
    ++count;
    sum += value;
    min = std::min(min, value);
    max = std::max(max, value);
  }
  [[nodiscard]] double mean() const { return count > 0 ? sum / static_cast<double>(count) : 0.0; }
};

// Keyed by metric name, in name order (deterministic output); looked up by string_view without
// allocating.
using ControllerMetrics = std::map<std::string, MetricSummary, std::less<>>;

// Adds one observation of `metric`, creating its summary on first use.
inline void record_metric(ControllerMetrics& metrics, std::string_view metric, double value) {
  auto it = metrics.find(metric);
  if (it == metrics.end()) it = metrics.emplace(std::string(metric), MetricSummary{}).first;
  it->second.add(value);
}

}  // namespace swarmnet
