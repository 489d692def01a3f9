// SDK test kit: the PluginArgs a kernel would hand a plugin, built from the plugin's own
// parameter table, so that a test constructs the plugin class directly.
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <variant>

#include "swarmnet/plugin.hpp"

namespace swarmnet::testing {

using ParamOverrides = std::map<std::string, ParamValue>;

// Every declared parameter at its default, then `overrides`, each checked against the table as
// the scenario validator would (declared, same type, inside the declared range or choices).
template <typename PluginClass>
PluginArgs plugin_args(const ParamOverrides& overrides = {}, std::uint64_t seed = 1,
                       std::uint32_t instance = 0, std::uint32_t instance_count = 1) {
  const PluginInfo info = PluginClass::info();
  PluginArgs args;
  for (const ParamSpec& spec : info.params) args.params.set(spec.name, spec.default_value);
  for (const auto& [name, value] : overrides) {
    const ParamSpec* spec = nullptr;
    for (const ParamSpec& s : info.params) {
      if (s.name == name) spec = &s;
    }
    const std::string where = "plugin_args<" + info.name + ">: parameter '" + name + "'";
    if (spec == nullptr) throw std::invalid_argument(where + " is not declared");
    if (value.index() != spec->default_value.index()) {
      throw std::invalid_argument(where + " should be " + to_string(spec->type));
    }
    double number = 0.0;
    if (const auto* real = std::get_if<double>(&value)) number = *real;
    if (const auto* integer = std::get_if<std::int64_t>(&value)) {
      number = static_cast<double>(*integer);
    }
    if ((spec->type == ParamType::real || spec->type == ParamType::integer) &&
        (number < spec->min || number > spec->max)) {
      throw std::invalid_argument(where + " is outside its declared range");
    }
    if (const auto* text = std::get_if<std::string>(&value);
        text != nullptr && !spec->choices.empty()) {
      bool listed = false;
      for (const std::string& choice : spec->choices) listed = listed || choice == *text;
      if (!listed) throw std::invalid_argument(where + " is not one of its choices");
    }
    args.params.set(name, value);
  }
  args.seed = seed;
  args.shared_seed = seed;
  args.instance = instance;
  args.instance_count = instance_count;
  return args;
}

}  // namespace swarmnet::testing
