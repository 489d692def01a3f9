// Finds plugins by name and creates instances of them.
//
// Search order (docs/plugins.md section 5): directories given by the scenario, then each
// directory in $SWARMNET_PLUGIN_PATH (colon-separated), then the plugin directory beside the
// running command (executable_layout.hpp). A plugin named NAME lives in a file swarmnet_NAME.so.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "plugin/plugin_error.hpp"
#include "plugin/plugin_instance.hpp"
#include "plugin/plugin_library.hpp"
#include "swarmnet/plugin.hpp"

namespace swarmnet {

// A library file that `discover()` could not open, with the reason.
struct BrokenPlugin {
  std::filesystem::path path;
  std::string error;
};

class PluginLoader {
 public:
  explicit PluginLoader(std::vector<std::filesystem::path> scenario_dirs = {});

  // Every directory searched, in order.
  [[nodiscard]] const std::vector<std::filesystem::path>& search_path() const {
    return search_path_;
  }

  // Puts `dirs` at the front of the search path, in the given order (a scenario's plugin_paths).
  // A directory already in the path moves to its new place rather than appearing twice. When the
  // path changes, the cache is cleared so that find() looks again.
  void prepend_directories(std::vector<std::filesystem::path> dirs);

  // The library of plugin `name`, opened once and cached. Throws PluginError naming the plugin,
  // every place searched, and the reason each candidate failed.
  std::shared_ptr<PluginLibrary> find(const std::string& name);
  // As find(), and refuses a plugin of another kind than `expected`.
  std::shared_ptr<PluginLibrary> find(const std::string& name, PluginKind expected);

  template <typename Interface>
  PluginInstance<Interface> create(const std::string& name, const PluginArgs& args) {
    auto library = find(name, Interface::kKind);
    std::unique_ptr<Plugin> object = library->descriptor().create(args);
    if (!object)
      throw PluginError("plugin '" + name + "' (" + library->path().string() +
                        ") returned no object");
    return PluginInstance<Interface>(std::move(library), std::move(object));
  }

  // The plugin names the search path offers, from file names alone (swarmnet_NAME.so), in name
  // order: nothing is opened, so no code of any library runs (for listing names in a message).
  [[nodiscard]] std::vector<std::string> names_in_search_path() const;

  // Every plugin in the search path, the first of each name winning (as find() would choose),
  // ordered by kind then name; files that failed to open go to `broken`.
  std::vector<std::shared_ptr<PluginLibrary>> discover(std::vector<BrokenPlugin>* broken = nullptr);

 private:
  std::vector<std::filesystem::path> search_path_;
  std::map<std::string, std::shared_ptr<PluginLibrary>> cache_;
};

// The file name a plugin called `name` is built to.
std::string plugin_file_name(const std::string& name);

}  // namespace swarmnet
