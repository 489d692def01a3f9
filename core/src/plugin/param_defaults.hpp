// The parameter set a plugin gets when a scenario sets none of its parameters.
#pragma once

#include "swarmnet/plugin.hpp"

namespace swarmnet {

inline ParamSet default_params(const PluginInfo& info) {
  ParamSet params;
  for (const auto& spec : info.params) params.set(spec.name, spec.default_value);
  return params;
}

}  // namespace swarmnet
