// Refuses, before anything runs, what of a scenario the ns-3 engine cannot run as asked
// (`network.engine: ns3`): a plugin with no ns-3 counterpart, a parameter or key given in the
// set to other than its default that ns-3 has no equivalent for, a rate ns-3's standard does not
// have. With the native engine it refuses ns-3-only keys set, rather than ignoring them. Every
// rule holds on a resolved scenario too (all values written out), which a network half
// validates again.
#pragma once

#include <yaml-cpp/yaml.h>

#include "plugin/plugin_loader.hpp"
#include "scenario/problem_list.hpp"
#include "scenario/scenario_checker.hpp"

namespace swarmnet {

// Runs on the checked tree. With ns3 and output.packet_trace absent, sets it to false (the ns-3
// engine writes no packets.csv), so that the resolved scenario says what the run writes.
void check_network_engine(YAML::Node& tree, const ScenarioChecker& checker, ProblemList& problems,
                          PluginLoader& loader);

}  // namespace swarmnet
