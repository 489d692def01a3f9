#include "robot/metric_series.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "text/csv_field.hpp"
#include "text/shortest_number.hpp"

namespace swarmnet {

void MetricSeries::sample(SimTime at, std::optional<RobotId> robot, std::string_view series,
                          double value) {
  const auto who = [&] {
    return robot ? "robot " + std::to_string(*robot) : std::string("a world");
  };
  if (series.empty()) throw std::invalid_argument(who() + ": sample() needs a series name");
  if (series.find_first_of("\r\n") != std::string_view::npos) {
    throw std::invalid_argument(who() + ": sample(): a series name must be one line");
  }
  if (!std::isfinite(value)) {
    throw std::invalid_argument(who() + ": sample(\"" + std::string(series) + "\", " +
                                std::to_string(value) + "): a series value must be finite");
  }
  if (out_ == nullptr) {
    if (!open_) throw std::logic_error(who() + ": sample(): this world writes no series.csv");
    out_ = &open_();
    *out_ << "time_ns,robot,series,value\n";
  }
  *out_ << at.count() << ',';
  if (robot) *out_ << *robot;
  *out_ << ',';
  write_csv_field(*out_, series);
  *out_ << ',';
  write_shortest(*out_, value);
  *out_ << '\n';
  ++rows_;
}

}  // namespace swarmnet
