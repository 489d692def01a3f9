// Every robot's heading at every step, beside positions.bin, for the viewer (docs/viewer.md):
// positions.bin holds x and y only, and a robot turning on the spot does not move.
//
// headings.bin, little-endian:
//   offset  0  char[8]  magic "SNHDG\0\0\0"
//           8  uint32   version (1)
//          12  uint32   robots
//          16  uint64   steps
//          24  int64    step_ns
//          32  then, for each step and each robot in id order: uint8 heading, the heading at the
//              start of the step in 256ths of a turn counter-clockwise from +x (1.4 degrees)
// The file is steps * robots + 32 bytes long. It is for drawing only: nothing reads it back into
// a simulation.
#pragma once

#include <cstdint>
#include <ostream>
#include <span>
#include <vector>

#include "swarmnet/robot_body.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

inline constexpr std::uint32_t kHeadingsTraceVersion = 1;
inline constexpr std::size_t kHeadingsHeaderBytes = 32;

// heading_rad as a 256th of a turn, in [0, 256).
std::uint8_t quantize_heading(double heading_rad);

class HeadingsTraceWriter {
 public:
  // Writes the header; then call sample() at most `steps` times, and finish().
  HeadingsTraceWriter(std::ostream& out, std::uint32_t robots, std::uint64_t steps, SimTime step);
  void sample(std::span<const RobotBody> bodies);
  // When fewer than `steps` samples were written, puts their number into the header (as
  // PositionsTraceWriter::finish). `out` must be seekable.
  void finish();

 private:
  std::ostream& out_;
  std::vector<char> buffer_;
  std::uint64_t declared_steps_ = 0;
  std::uint64_t written_steps_ = 0;
};

}  // namespace swarmnet
