// Geometry for the "do the robots fit?" check.
#pragma once

#include <vector>

#include "swarmnet/vector.hpp"

namespace swarmnet {

// The area of `region` (m^2) that no obstacle covers. Obstacles may overlap one another and
// stick out of the region; each part is counted once.
double free_area(const Rect& region, const std::vector<Rect>& obstacles);

}  // namespace swarmnet
