// Exact robot positions, every step, for replaying the network half bit for bit (`swarmnet
// replay`). The ns-2 mobility trace rounds to 6 decimals, too coarse for an identical packet
// trace; this record keeps the doubles the network half was given.
//
// positions.bin, all integers and doubles little-endian:
//   offset  0  char[8]  magic "SNPOS\0\0\0"
//           8  uint32   version (1)
//          12  uint32   robots
//          16  uint64   steps
//          24  int64    step_ns (length of one step in nanoseconds)
//          32  then, for each step in order and each robot in id order: double x_m, double y_m
//              (the position at the start of the step, as sent to the network half)
// The file is steps * robots * 16 + 32 bytes long; a reader refuses any other length.
#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <span>
#include <vector>

#include "swarmnet/units.hpp"
#include "swarmnet/vector.hpp"

namespace swarmnet {

inline constexpr std::uint32_t kPositionsTraceVersion = 1;
inline constexpr std::size_t kPositionsHeaderBytes = 32;

class PositionsTraceWriter {
 public:
  // Writes the header; then call sample() at most `steps` times with `robots` positions each, and
  // finish().
  PositionsTraceWriter(std::ostream& out, std::uint32_t robots, std::uint64_t steps, SimTime step);
  void sample(std::span<const Vec2> positions);
  // When fewer than `steps` samples were written (a world plugin ended the run early), puts their
  // number into the header, so that the file is whole for what it holds. `out` must be seekable.
  void finish();

 private:
  std::ostream& out_;
  std::vector<char> buffer_;
  std::uint64_t declared_steps_ = 0;
  std::uint64_t written_steps_ = 0;
};

struct PositionsTrace {
  std::uint32_t robots = 0;
  std::uint64_t steps = 0;
  SimTime step{};
  std::vector<Vec2> positions;  // steps * robots, step-major

  [[nodiscard]] std::span<const Vec2> at_step(std::uint64_t step_index) const {
    return std::span<const Vec2>(positions).subspan(step_index * robots, robots);
  }
};

// Reads and checks a positions.bin; throws RunError naming the file and what is wrong.
PositionsTrace read_positions_trace(const std::filesystem::path& path);

}  // namespace swarmnet
