// One opened plugin library: an RAII handle over dlopen/dlclose with its checked descriptor.
#pragma once

#include <filesystem>
#include <memory>

#include "swarmnet/plugin.hpp"

namespace swarmnet {

class PluginLibrary {
 public:
  // Opens `path` with RTLD_NOW | RTLD_LOCAL (a missing symbol fails here, not mid-run), finds the
  // entry symbol and checks the ABI version before reading the descriptor, then the plugin's own
  // table (plugin_table_check.hpp). Throws PluginError naming the path and dlerror()'s text, or
  // both ABI versions, or the parameter the table gets wrong.
  static std::shared_ptr<PluginLibrary> open(const std::filesystem::path& path);

  PluginLibrary(const PluginLibrary&) = delete;
  PluginLibrary& operator=(const PluginLibrary&) = delete;
  PluginLibrary(PluginLibrary&&) = delete;
  PluginLibrary& operator=(PluginLibrary&&) = delete;
  ~PluginLibrary();

  [[nodiscard]] const PluginDescriptor& descriptor() const { return *descriptor_; }
  [[nodiscard]] const PluginInfo& info() const { return descriptor_->info; }
  [[nodiscard]] PluginKind kind() const { return descriptor_->kind; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  PluginLibrary(void* handle, const PluginDescriptor* descriptor, std::filesystem::path path)
      : handle_(handle), descriptor_(descriptor), path_(std::move(path)) {}

  void* handle_;
  const PluginDescriptor* descriptor_;
  std::filesystem::path path_;
};

}  // namespace swarmnet
