// What controllers record through RobotContext::record(): each metric pooled over all robots
// (summary.json's "controllers") and per robot (robot_metrics.csv), from one lookup per
// observation.
//
// robot_metrics.csv, written when any controller recorded something:
//
//   robot,metric,count,sum,mean,min,max
//
// one row per robot and metric it recorded, ascending by robot, then by metric name; numbers in
// their shortest exact form; a name with a comma, quote or line break quoted as CSV quotes it.
#pragma once

#include <cstddef>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "robot/controller_metrics.hpp"
#include "swarmnet/ids.hpp"

namespace swarmnet {

class RobotMetrics {
 public:
  explicit RobotMetrics(std::size_t robots = 0) : per_robot_(robots) {}

  // Adds one observation of `metric` by `robot` (< the robot count given at construction).
  void add(RobotId robot, std::string_view metric, double value);

  [[nodiscard]] bool empty() const { return columns_.empty(); }
  // Every metric pooled over all robots, in name order.
  [[nodiscard]] ControllerMetrics pooled() const;
  // Robot `robot`'s summary of `metric`; count 0 when it recorded none.
  [[nodiscard]] MetricSummary of(RobotId robot, std::string_view metric) const;
  void write_csv(std::ostream& out) const;

 private:
  struct Column {
    std::size_t index = 0;  // into each robot's row of summaries
    MetricSummary pooled;
  };

  std::map<std::string, Column, std::less<>> columns_;
  std::vector<std::vector<MetricSummary>> per_robot_;  // [robot][column index]
};

}  // namespace swarmnet
