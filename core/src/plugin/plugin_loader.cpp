#include "plugin/plugin_loader.hpp"

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <set>
#include <sstream>
#include <system_error>

#include "plugin/executable_layout.hpp"

namespace swarmnet {

namespace {

std::vector<std::filesystem::path> split_path_list(const char* list) {
  std::vector<std::filesystem::path> dirs;
  if (list == nullptr) return dirs;
  std::stringstream stream(list);
  std::string item;
  while (std::getline(stream, item, ':')) {
    if (!item.empty()) dirs.emplace_back(item);
  }
  return dirs;
}

constexpr std::string_view kFilePrefix = "swarmnet_";
constexpr std::string_view kFileSuffix = ".so";

}  // namespace

std::string plugin_file_name(const std::string& name) {
  return std::string(kFilePrefix) + name + std::string(kFileSuffix);
}

PluginLoader::PluginLoader(std::vector<std::filesystem::path> scenario_dirs)
    : search_path_(std::move(scenario_dirs)) {
  for (auto& dir : split_path_list(std::getenv("SWARMNET_PLUGIN_PATH"))) {
    search_path_.push_back(std::move(dir));
  }
  // The plugins beside the command (<prefix>/lib/swarmnet/plugins installed, <build>/plugins in
  // a build tree), found from its executable: no build or install path is compiled in.
  const auto own = executable_layout().plugin_dir;
  if (!own.empty()) search_path_.push_back(own);
}

void PluginLoader::prepend_directories(std::vector<std::filesystem::path> dirs) {
  std::vector<std::filesystem::path> path;
  for (auto& dir : dirs) {
    if (std::find(path.begin(), path.end(), dir) == path.end()) path.push_back(std::move(dir));
  }
  for (const auto& dir : search_path_) {
    if (std::find(path.begin(), path.end(), dir) == path.end()) path.push_back(dir);
  }
  if (path != search_path_) {
    search_path_ = std::move(path);
    cache_.clear();
  }
}

std::shared_ptr<PluginLibrary> PluginLoader::find(const std::string& name) {
  if (auto it = cache_.find(name); it != cache_.end()) return it->second;
  const std::string file = plugin_file_name(name);
  std::ostringstream tried;
  for (auto dir = search_path_.begin(); dir != search_path_.end(); ++dir) {
    const auto candidate = *dir / file;
    std::error_code ec;
    if (!std::filesystem::exists(candidate, ec)) {
      tried << "\n  " << candidate.string() << ": no such file";
      continue;
    }
    try {
      auto library = PluginLibrary::open(candidate);
      if (library->info().name != name) {
        tried << "\n  " << candidate.string() << ": declares the name '" << library->info().name
              << "'";
        continue;
      }
      cache_.emplace(name, library);
      return library;
    } catch (const PluginError& error) {
      // A broken candidate is reported, not skipped silently: finding a later one would hide it.
      // But a later file of the same name may be the one meant, hidden by this one: say so.
      std::string hidden;
      for (auto later = std::next(dir); later != search_path_.end(); ++later) {
        if (std::filesystem::exists(*later / file, ec)) hidden += "\n  " + (*later / file).string();
      }
      if (!hidden.empty()) {
        hidden =
            "\nThe first file found wins, and it hides another of the same name later on the "
            "search path:" +
            hidden + "\n(remove or rebuild the broken one, or reorder the search path)";
      }
      throw PluginError("plugin '" + name + "': " + error.what() + hidden);
    }
  }
  throw PluginError(
      "plugin '" + name + "' not found; searched:" + tried.str() +
      "\n(add a directory with plugin_paths in the scenario or SWARMNET_PLUGIN_PATH)");
}

std::shared_ptr<PluginLibrary> PluginLoader::find(const std::string& name, PluginKind expected) {
  auto library = find(name);
  if (library->kind() != expected) {
    throw PluginError("plugin '" + name + "' (" + library->path().string() + ") is a " +
                      to_string(library->kind()) + " plugin; a " + to_string(expected) +
                      " plugin is expected here");
  }
  return library;
}

std::vector<std::string> PluginLoader::names_in_search_path() const {
  std::set<std::string> names;
  for (const auto& dir : search_path_) {
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      const std::string file = entry.path().filename().string();
      if (file.size() > kFilePrefix.size() + kFileSuffix.size() && file.starts_with(kFilePrefix) &&
          file.ends_with(kFileSuffix)) {
        names.insert(
            file.substr(kFilePrefix.size(), file.size() - kFilePrefix.size() - kFileSuffix.size()));
      }
    }
  }
  return {names.begin(), names.end()};
}

std::vector<std::shared_ptr<PluginLibrary>> PluginLoader::discover(
    std::vector<BrokenPlugin>* broken) {
  std::set<std::string> seen;
  std::vector<std::shared_ptr<PluginLibrary>> found;
  for (const auto& dir : search_path_) {
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) continue;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
      const std::string file = entry.path().filename().string();
      if (file.starts_with(kFilePrefix) && file.ends_with(kFileSuffix))
        files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());  // directory order is not deterministic
    for (const auto& path : files) {
      const std::string file = path.filename().string();
      const std::string name =
          file.substr(kFilePrefix.size(), file.size() - kFilePrefix.size() - kFileSuffix.size());
      if (seen.contains(name)) continue;
      seen.insert(name);
      try {
        auto library = PluginLibrary::open(path);
        cache_.try_emplace(library->info().name, library);
        found.push_back(std::move(library));
      } catch (const PluginError& error) {
        if (broken != nullptr) broken->push_back({path, error.what()});
      }
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const auto& a, const auto& b) {
    if (a->kind() != b->kind()) return a->kind() < b->kind();
    return a->info().name < b->info().name;
  });
  return found;
}

}  // namespace swarmnet
