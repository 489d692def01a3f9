// Reading a scenario file: parse, apply command-line overrides, validate everything, resolve
// plugins and defaults. The key reference is docs/scenario.md.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "plugin/plugin_loader.hpp"
#include "scenario/scenario.hpp"

namespace swarmnet {

// The largest scenario file read (a scenario with 100,000 obstacles is about 8 MiB).
inline constexpr std::uintmax_t kMaxScenarioFileBytes = std::uintmax_t{64} << 20U;

struct ScenarioOverrides {
  std::vector<std::string> set;                  // "a.b.c=VALUE", applied in order
  std::optional<std::uint64_t> seed;             // --seed: replaces `seed`
  std::optional<std::filesystem::path> out_dir;  // --out: replaces output.dir
  // A server's own plugin search path (`swarmnet net --listen`): the text's plugin_paths is
  // never looked up on this host nor searched (ScenarioChecker::ignore_directory_lists); the
  // Scenario gets these.
  std::optional<std::vector<std::filesystem::path>> host_plugin_paths;
};

// Every problem found in a scenario. what() holds them one per line, each
// "FILE:LINE:COLUMN: KEY.PATH: what is wrong; expected FORM" (or "--set KEY.PATH: ..." for a value
// given on the command line).
class ScenarioError : public std::runtime_error {
 public:
  explicit ScenarioError(std::vector<std::string> problems);
  [[nodiscard]] const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

// Loads `file`, applies `overrides` (--set first, then --seed and --out), and checks every key,
// every plugin (found through `loader`, whose search path gains the scenario's plugin_paths at
// the front) and every plugin parameter, reporting all problems at once as a ScenarioError.
Scenario load_scenario(const std::filesystem::path& file, const ScenarioOverrides& overrides,
                       PluginLoader& loader);

// As load_scenario(), from YAML text (the resolved scenario the robot half sends to the network
// half). `origin` stands for the file name in messages and in Scenario::source; relative
// plugin_paths are relative to the current working directory (a resolved scenario has none).
Scenario load_scenario_text(const std::string& yaml, const std::string& origin,
                            PluginLoader& loader, const ScenarioOverrides& overrides = {});

// A scenario as a server (`swarmnet net --listen`) reads a peer's hello: once, as
// load_scenario_text(), with `host_plugin_paths` as the plugin search path whatever the text says
// (no path the text's plugin_paths holds is looked up or searched on this host).
Scenario load_peer_scenario_text(const std::string& yaml, const std::string& origin,
                                 PluginLoader& loader,
                                 const std::vector<std::filesystem::path>& host_plugin_paths);

// Scenario::resolved as YAML text (scenario.resolved.yaml): equal scenarios give equal bytes, and
// loading the text again gives the same scenario.
std::string resolved_yaml(const Scenario& scenario);

// One row of the key reference: what docs/scenario.md documents for every key.
struct ScenarioKeyInfo {
  std::string path;      // "robots.proximity.rays"; list elements as "arena.obstacles[].x_min_m"
  std::string form;      // "integer 0..360"
  std::string unit;      // "m", "" when none
  std::string fallback;  // the default as YAML, "" when required
  bool required = false;
  std::string help;
};
std::vector<ScenarioKeyInfo> scenario_key_reference();

}  // namespace swarmnet
