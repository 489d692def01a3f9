#include "robot/robot_metrics.hpp"

#include "text/csv_field.hpp"
#include "text/shortest_number.hpp"

namespace swarmnet {

void RobotMetrics::add(RobotId robot, std::string_view metric, double value) {
  auto it = columns_.find(metric);
  if (it == columns_.end()) {
    it = columns_.emplace(std::string(metric), Column{columns_.size(), {}}).first;
  }
  it->second.pooled.add(value);
  std::vector<MetricSummary>& row = per_robot_.at(robot);
  if (row.size() <= it->second.index) row.resize(it->second.index + 1);
  row[it->second.index].add(value);
}

ControllerMetrics RobotMetrics::pooled() const {
  ControllerMetrics metrics;
  for (const auto& [name, column] : columns_) metrics.emplace(name, column.pooled);
  return metrics;
}

MetricSummary RobotMetrics::of(RobotId robot, std::string_view metric) const {
  const auto it = columns_.find(metric);
  const std::vector<MetricSummary>& row = per_robot_.at(robot);
  if (it == columns_.end() || it->second.index >= row.size()) return {};
  return row[it->second.index];
}

void RobotMetrics::write_csv(std::ostream& out) const {
  out << "robot,metric,count,sum,mean,min,max\n";
  for (std::size_t robot = 0; robot < per_robot_.size(); ++robot) {
    const std::vector<MetricSummary>& row = per_robot_[robot];
    for (const auto& [name, column] : columns_) {
      if (column.index >= row.size() || row[column.index].count == 0) continue;
      const MetricSummary& summary = row[column.index];
      out << robot << ',';
      write_csv_field(out, name);
      out << ',' << summary.count << ',';
      write_shortest(out, summary.sum);
      out << ',';
      write_shortest(out, summary.mean());
      out << ',';
      write_shortest(out, summary.min);
      out << ',';
      write_shortest(out, summary.max);
      out << '\n';
    }
  }
}

}  // namespace swarmnet
