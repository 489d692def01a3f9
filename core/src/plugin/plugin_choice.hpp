// One plugin as a scenario chose it: its name, kind and validated parameters. The engines take
// these in their typed settings; the scenario loader is what makes them.
#pragma once

#include <string>

#include "swarmnet/params.hpp"
#include "swarmnet/plugin.hpp"

namespace swarmnet {

// Where a value came from, for error messages: "file.yaml:12:5" or "--set robots.count".
struct SourceLocation {
  std::string text;
};

struct PluginChoice {
  std::string name;
  PluginKind kind = PluginKind::controller;
  ParamSet params;
  SourceLocation where;
};

}  // namespace swarmnet
