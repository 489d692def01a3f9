#include "outputs/mobility_trace.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>

namespace swarmnet {

MobilityTraceWriter::MobilityTraceWriter(std::ostream& out, std::uint64_t interval_steps,
                                         double step_s)
    : out_(out), interval_steps_(std::max<std::uint64_t>(1, interval_steps)), step_s_(step_s) {}

void MobilityTraceWriter::sample(std::uint64_t step, std::span<const Vec2> positions) {
  char line[160];
  if (previous_.empty()) {
    for (std::size_t i = 0; i < positions.size(); ++i) {
      std::snprintf(line, sizeof line,
                    "$node_(%zu) set X_ %.6f\n$node_(%zu) set Y_ %.6f\n"
                    "$node_(%zu) set Z_ 0.000000\n",
                    i, positions[i].x(), i, positions[i].y(), i);
      out_ << line;
    }
    previous_.assign(positions.begin(), positions.end());
    previous_step_ = step;
    return;
  }
  if (step % interval_steps_ != 0) return;
  // The segment from the previous sample to this one starts at the previous sample's time.
  const double start_s = static_cast<double>(previous_step_) * step_s_;
  const double span_s = static_cast<double>(step - previous_step_) * step_s_;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const double distance = (positions[i] - previous_[i]).norm();
    if (distance == 0.0) continue;
    std::snprintf(line, sizeof line, "$ns_ at %.6f \"$node_(%zu) setdest %.6f %.6f %.6f\"\n",
                  start_s, i, positions[i].x(), positions[i].y(), distance / span_s);
    out_ << line;
  }
  previous_.assign(positions.begin(), positions.end());
  previous_step_ = step;
}

}  // namespace swarmnet
