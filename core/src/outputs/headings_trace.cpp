#include "outputs/headings_trace.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <numbers>

#include "outputs/file_buffer.hpp"
#include "outputs/run_error.hpp"

namespace swarmnet {

namespace {

constexpr std::array<char, 8> kMagic = {'S', 'N', 'H', 'D', 'G', '\0', '\0', '\0'};

void put_le(char* out, std::uint64_t value, std::size_t bytes) {
  for (std::size_t i = 0; i < bytes; ++i) out[i] = static_cast<char>(value >> (8 * i));
}

}  // namespace

std::uint8_t quantize_heading(double heading_rad) {
  if (!std::isfinite(heading_rad)) return 0;
  const double turns = heading_rad / (2.0 * std::numbers::pi);
  const double fraction = turns - std::floor(turns);
  return static_cast<std::uint8_t>(static_cast<long>(std::lround(fraction * 256.0)) & 255);
}

HeadingsTraceWriter::HeadingsTraceWriter(std::ostream& out, std::uint32_t robots,
                                         std::uint64_t steps, SimTime step)
    : out_(out), declared_steps_(steps) {
  std::array<char, kHeadingsHeaderBytes> header{};
  std::memcpy(header.data(), kMagic.data(), kMagic.size());
  put_le(header.data() + 8, kHeadingsTraceVersion, 4);
  put_le(header.data() + 12, robots, 4);
  put_le(header.data() + 16, steps, 8);
  put_le(header.data() + 24, static_cast<std::uint64_t>(step.count()), 8);
  out_.write(header.data(), static_cast<std::streamsize>(header.size()));
}

void HeadingsTraceWriter::sample(std::span<const RobotBody> bodies) {
  buffer_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    buffer_[i] = static_cast<char>(quantize_heading(bodies[i].heading_rad));
  }
  out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  ++written_steps_;
}

void HeadingsTraceWriter::finish() {
  if (written_steps_ == declared_steps_) return;
  std::array<char, 8> steps{};
  put_le(steps.data(), written_steps_, 8);
  const std::streampos end = out_.tellp();
  out_.seekp(16);
  out_.write(steps.data(), static_cast<std::streamsize>(steps.size()));
  out_.seekp(end);
  if (!out_) {
    throw RunError("cannot record the step count in the headings trace's header: " +
                   write_failure(out_));
  }
}

}  // namespace swarmnet
