// The SDK test kit in one include: a deterministic scheduler, fake robot, world and node contexts,
// packet and frame builders, and a plugin's PluginArgs from its own table. A plugin's tests use
// only these and the SDK, never the kernel (docs/plugins.md, "Testing a plugin").
#pragma once

#include "swarmnet/testing/fake_node.hpp"
#include "swarmnet/testing/fake_robot_context.hpp"
#include "swarmnet/testing/fake_world_context.hpp"
#include "swarmnet/testing/packet_builder.hpp"
#include "swarmnet/testing/plugin_args.hpp"
#include "swarmnet/testing/test_scheduler.hpp"
