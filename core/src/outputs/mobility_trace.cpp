#include "outputs/mobility_trace.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstddef>

namespace swarmnet {

namespace {

// The trace's numbers as printf's "%.6f" and "%zu" write them: std::to_chars with a precision is
// specified to give printf's characters in the C locale, without printf's cost (glibc's "%f" is
// multi-precision arithmetic, and was most of the robot half's time at 400 robots).
void append_fixed6(std::string& out, double value) {
  // The longest double in fixed notation: 309 integer digits, a sign, a point and 6 decimals.
  std::array<char, 320> digits{};
  const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), value,
                                    std::chars_format::fixed, 6);
  out.append(digits.data(), result.ptr);
}

void append_index(std::string& out, std::size_t value) {
  std::array<char, 24> digits{};
  const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), value);
  out.append(digits.data(), result.ptr);
}

void append_node(std::string& out, std::size_t node) {
  out += "$node_(";
  append_index(out, node);
  out += ')';
}

}  // namespace

MobilityTraceWriter::MobilityTraceWriter(std::ostream& out, std::uint64_t interval_steps,
                                         double step_s)
    : out_(out), interval_steps_(std::max<std::uint64_t>(1, interval_steps)), step_s_(step_s) {}

void MobilityTraceWriter::sample(std::uint64_t step, std::span<const Vec2> positions) {
  text_.clear();
  if (previous_.empty()) {
    for (std::size_t i = 0; i < positions.size(); ++i) {
      append_node(text_, i);
      text_ += " set X_ ";
      append_fixed6(text_, positions[i].x());
      text_ += '\n';
      append_node(text_, i);
      text_ += " set Y_ ";
      append_fixed6(text_, positions[i].y());
      text_ += '\n';
      append_node(text_, i);
      text_ += " set Z_ 0.000000\n";
    }
    out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
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
    text_ += "$ns_ at ";
    append_fixed6(text_, start_s);
    text_ += " \"";
    append_node(text_, i);
    text_ += " setdest ";
    append_fixed6(text_, positions[i].x());
    text_ += ' ';
    append_fixed6(text_, positions[i].y());
    text_ += ' ';
    append_fixed6(text_, distance / span_s);
    text_ += "\"\n";
  }
  out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
  previous_.assign(positions.begin(), positions.end());
  previous_step_ = step;
}

}  // namespace swarmnet
