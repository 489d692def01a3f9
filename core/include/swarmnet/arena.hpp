// The world robots move in: a walled rectangle [0, width] x [0, height] with rectangular obstacles.
#pragma once

#include <vector>

#include "swarmnet/vector.hpp"

namespace swarmnet {

struct Arena {
  double width_m = 0.0;
  double height_m = 0.0;
  std::vector<Rect> obstacles;
};

}  // namespace swarmnet
