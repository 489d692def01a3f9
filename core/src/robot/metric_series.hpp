// Time series that controllers and world plugins write through sample(): one row per call, in
// the order of the calls (steps in order; in a step, the worlds' pre_step, robots in ascending
// id, the worlds' post_step), written to series.csv as they come, so a long run holds none of
// them in memory:
//
//   time_ns,robot,series,value
//
// time_ns is the simulated time of the call (RobotContext::now() or WorldContext::now()); robot
// is the robot's id, empty for a world plugin's sample; series is the name given, quoted as CSV
// quotes it when it holds a comma, quote or line break; value in its shortest exact form. The
// file is opened at the first sample, so a run that samples nothing writes none.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <ostream>
#include <string_view>
#include <utility>

#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

class MetricSeries {
 public:
  // `open` opens series.csv; called at most once, at the first sample. Without it, sample()
  // throws std::logic_error (a world built without a run directory, as in a kernel test).
  explicit MetricSeries(std::function<std::ostream&()> open = {}) : open_(std::move(open)) {}

  // Throws std::invalid_argument for an empty name, one with a line break, or a value that is not
  // finite (a NaN in a plotted series hides a bug where it happened).
  void sample(SimTime at, std::optional<RobotId> robot, std::string_view series, double value);
  [[nodiscard]] std::uint64_t rows() const { return rows_; }

 private:
  std::function<std::ostream&()> open_;
  std::ostream* out_ = nullptr;
  std::uint64_t rows_ = 0;
};

}  // namespace swarmnet
