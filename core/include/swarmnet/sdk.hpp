// Everything a plugin may include, in one header.
#pragma once

#include "swarmnet/arena.hpp"
#include "swarmnet/controller.hpp"
#include "swarmnet/ids.hpp"
#include "swarmnet/mac.hpp"
#include "swarmnet/node_context.hpp"
#include "swarmnet/packet.hpp"
#include "swarmnet/params.hpp"
#include "swarmnet/physics.hpp"
#include "swarmnet/plugin.hpp"
#include "swarmnet/propagation.hpp"
#include "swarmnet/random.hpp"
#include "swarmnet/robot_body.hpp"
#include "swarmnet/routing.hpp"
#include "swarmnet/spatial_grid.hpp"
#include "swarmnet/units.hpp"
#include "swarmnet/vector.hpp"
