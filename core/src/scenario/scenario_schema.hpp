// The scenario's keys as data: one row per key with its form, rule, default and help. The checker
// (scenario_checker.hpp) walks this table, the resolved scenario is written in its order, and
// scenario_key_reference() lists it for the documentation. Adding a key is one row here (and one
// line reading it into Scenario in scenario_loader.cpp).
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "scenario/scalar_rule.hpp"
#include "swarmnet/plugin.hpp"

namespace swarmnet {

enum class KeyForm : std::uint8_t {
  scalar,          // checked by `rule`
  directory_list,  // list of directories, relative to the scenario file's directory
  map,             // mapping of `keys`
  map_list,        // list of mappings of `keys`
  plugin,          // {plugin: NAME, params: {...}} of `plugin_kind`
  plugin_list,     // list of those
};

struct KeySpec {
  std::string name;
  KeyForm form = KeyForm::scalar;
  ScalarRule rule;
  std::string help;
  bool required = false;
  std::optional<std::string> default_yaml;  // what an absent key becomes, as YAML text
  std::string computed;                     // when absent, derived later (text for the docs)
  std::vector<KeySpec> keys;                // map: its keys; map_list: each element's keys
  PluginKind plugin_kind = PluginKind::controller;
  std::string default_plugin;  // plugin: the name used when `plugin:` is absent
  std::size_t min_items = 0;   // lists
  bool flow = false;           // written on one line in the resolved scenario

  // Required keys must be given. A mapping is also required when it is not computed and any of
  // its keys is; otherwise an absent mapping is read as an empty one, filling defaults.
  [[nodiscard]] bool is_required() const;
  [[nodiscard]] const KeySpec* find(const std::string& key) const;
  [[nodiscard]] std::vector<std::string> key_names() const;
  // The expected form, as messages and the reference state it.
  [[nodiscard]] std::string describe() const;

  // Builders, so that the table reads as rows.
  KeySpec need() && {
    required = true;
    return std::move(*this);
  }
  KeySpec defaults(std::string yaml) && {
    default_yaml = std::move(yaml);
    return std::move(*this);
  }
  KeySpec derived(std::string text) && {
    computed = std::move(text);
    return std::move(*this);
  }
  KeySpec above(double low) && {
    rule.min = low;
    rule.min_open = true;
    return std::move(*this);
  }
  KeySpec at_least(double low) && {
    rule.min = low;
    return std::move(*this);
  }
  KeySpec between(double low, double high) && {
    rule.min = low;
    rule.max = high;
    return std::move(*this);
  }
  KeySpec at_least_items(std::size_t n) && {
    min_items = n;
    return std::move(*this);
  }
  KeySpec plugin_default(std::string plugin) && {
    default_plugin = std::move(plugin);
    return std::move(*this);
  }
  KeySpec one_line() && {
    flow = true;
    return std::move(*this);
  }
};

KeySpec real_key(std::string name, std::string unit, std::string help);
KeySpec integer_key(std::string name, std::string help);
KeySpec boolean_key(std::string name, std::string help);
KeySpec text_key(std::string name, std::string help);
KeySpec name_key(std::string name, std::string help);
KeySpec choice_key(std::string name, std::vector<std::string> choices, std::string help);
KeySpec directory_list_key(std::string name, std::string help);
KeySpec map_key(std::string name, std::string help, std::vector<KeySpec> keys);
KeySpec map_list_key(std::string name, std::string help, std::vector<KeySpec> keys);
KeySpec plugin_key(std::string name, PluginKind kind, std::string help);
KeySpec plugin_list_key(std::string name, PluginKind kind, std::string help);

// The whole scenario: a mapping with an empty name.
const KeySpec& scenario_schema();

}  // namespace swarmnet
