// A choice of a plugin with every parameter at its declared default: what a scenario
// that names the plugin and sets nothing resolves to. For tests and benchmarks that build
// settings in code.
#pragma once

#include <string>

#include "plugin/param_defaults.hpp"
#include "plugin/plugin_choice.hpp"
#include "plugin/plugin_loader.hpp"

namespace swarmnet {

inline PluginChoice default_plugin_choice(PluginLoader& loader, const std::string& name,
                                          PluginKind kind) {
  PluginChoice choice;
  choice.name = name;
  choice.kind = kind;
  choice.params = default_params(loader.find(name, kind)->info());
  return choice;
}

}  // namespace swarmnet
