// `--set KEY.PATH=VALUE`: command-line changes to a scenario's YAML tree, applied before it is
// checked, so an overridden value is validated exactly like one written in the file.
//
// KEY.PATH is a list of components separated by '.': a component indexes a list when the node it
// applies to is a list (robots.controllers.1.params.rate_hz), and names a key otherwise. Missing
// keys are created (the check then refuses unknown ones). VALUE is read as YAML: a scalar, a flow
// list [a, b] or a flow mapping {k: v}; an empty VALUE is null.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "scenario/problem_list.hpp"

namespace swarmnet {

// Applies `overrides` in order (a later one wins) to the mapping `root`. A malformed override (no
// '=', an empty path or component, an index out of range, a path through a scalar, a value that
// is not YAML) is reported to `problems` and skipped. Each applied override marks its path in
// `problems`, so that later problems under it are located at "--set KEY.PATH".
void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides,
                     ProblemList& problems);

}  // namespace swarmnet
