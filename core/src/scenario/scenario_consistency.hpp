// Checks that relate several keys, run on the checked tree after every key was checked alone:
// whole steps, obstacles and the placement region inside the arena, robots that can fit. Also
// derives the placement region when it is not given (the whole arena).
#pragma once

#include <yaml-cpp/yaml.h>

#include "scenario/problem_list.hpp"
#include "scenario/scenario_checker.hpp"

namespace swarmnet {

// The most steps a run may have (keeps step numbers and times far from overflow).
inline constexpr double kMaxSteps = 1e12;

// A check runs only when the keys it needs passed their own checks; `tree` is the checker's
// normalized tree and gains robots.placement.region when it was absent.
void check_consistency(YAML::Node& tree, const ScenarioChecker& checker, ProblemList& problems);

}  // namespace swarmnet
