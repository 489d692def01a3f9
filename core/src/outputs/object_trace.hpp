// Poses of the arena's movable objects (arena.objects), every step, as CSV beside positions.bin:
//   step,time_ns,object,x_m,y_m,heading_rad
// one row per object (in scenario order) per step, the pose at the start of the step, as the
// robots' positions in positions.bin. Numbers are written in the shortest form that reads back
// to the same double, so the file is exact and byte-identical between identical runs.
#pragma once

#include <cstdint>
#include <ostream>
#include <span>

#include "swarmnet/physics.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

class ObjectTraceWriter {
 public:
  ObjectTraceWriter(std::ostream& out, SimTime step);
  void sample(std::uint64_t step_index, std::span<const ObjectPose> poses);

 private:
  std::ostream& out_;
  SimTime step_;
};

}  // namespace swarmnet
