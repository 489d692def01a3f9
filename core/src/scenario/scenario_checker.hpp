// Checks a scenario's YAML tree against the schema (scenario_schema.hpp) and each plugin's
// parameter schema, reporting every problem, and produces the normalized tree: keys in schema
// order, defaults filled, every plugin with its full parameter map, invalid values left out.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "plugin/plugin_loader.hpp"
#include "scenario/key_path.hpp"
#include "scenario/problem_list.hpp"
#include "scenario/scenario.hpp"
#include "scenario/scenario_schema.hpp"

namespace swarmnet {

// The node at `path` of a checked tree (a list element by its index), if it is there: an absent
// or invalid value is not, since the checker leaves those out.
std::optional<YAML::Node> checked_node_at(const YAML::Node& tree, const KeyPath& path);

class ScenarioChecker {
 public:
  // `base_dir` is the scenario file's directory (for relative plugin_paths). Directories of a
  // directory_list key are added to `loader`'s search path as soon as they are checked.
  ScenarioChecker(ProblemList& problems, PluginLoader& loader, std::filesystem::path base_dir);

  // For a server reading a peer's scenario: a directory_list key (plugin_paths) names folders of
  // another host, so its value is never looked up here nor added to the loader; it checks as an
  // empty list (a repeated key is still refused). The server supplies its own directories.
  void ignore_directory_lists() { ignore_directory_lists_ = true; }

  // The normalized tree of `root` against the mapping `schema`.
  YAML::Node check_root(const KeySpec& schema, const YAML::Node& root);

  // Every valid plugin key, by key path text ("network.routing", "robots.controllers.0").
  [[nodiscard]] const std::map<std::string, PluginChoice>& plugins() const { return plugins_; }

  // The YAML mark of the value checked at `path`: of the value, or of the nearest mapping given
  // when the value took its default; null when it was never checked.
  [[nodiscard]] YAML::Mark mark_of(const KeyPath& path) const;

  // True when the scenario gave the value at `path` itself (it did not take a default, alone or
  // as part of a defaulted mapping).
  [[nodiscard]] bool given(const KeyPath& path) const;

 private:
  struct Where {
    KeyPath path;
    YAML::Mark mark;  // of the value, or of its key when the value is empty
  };
  struct Entry {
    std::string key;
    YAML::Node value;
    Where where;
  };

  std::optional<YAML::Node> check(const KeySpec& spec, const YAML::Node& value, const Where& where);
  std::optional<YAML::Node> check_map(const KeySpec& spec, const YAML::Node& value,
                                      const Where& where);
  std::optional<YAML::Node> check_list(const KeySpec& spec, const YAML::Node& value,
                                       const Where& where);
  std::optional<YAML::Node> check_directory(const YAML::Node& value, const Where& where);
  std::optional<YAML::Node> check_plugin(const KeySpec& spec, const YAML::Node& value,
                                         const Where& where);
  std::optional<YAML::Node> check_plugin_params(const PluginLibrary& library,
                                                const YAML::Node& value, const Where& where,
                                                ParamSet* params);
  std::optional<YAML::Node> absent(const KeySpec& spec, const Where& parent);

  // The entries of mapping `value`, each key once; reports non-text keys, repeated keys and keys
  // not in `known` (naming the nearest known one).
  std::vector<Entry> entries(const YAML::Node& value, const Where& where,
                             const std::vector<std::string>& known, const std::string& unknown_what,
                             const std::string& known_hint,
                             const std::string& none_known = "no keys here");
  // The plugins of `kind` in the search path, for "expected one of" after a failed lookup.
  [[nodiscard]] std::string available_plugins() const;

  void remember(const Where& where) { marks_[where.path.text()] = where.mark; }

  ProblemList& problems_;
  PluginLoader& loader_;
  std::filesystem::path base_dir_;
  bool ignore_directory_lists_ = false;
  std::map<std::string, PluginChoice> plugins_;
  std::map<std::string, YAML::Mark> marks_;
  std::vector<KeyPath> defaulted_;  // keys that were absent and took their schema default
};

}  // namespace swarmnet
