#include "plugin/plugin_library.hpp"

#include <dlfcn.h>

#include <string>

#include "plugin/plugin_error.hpp"
#include "plugin/plugin_table_check.hpp"

namespace swarmnet {

namespace {

std::string last_dl_error() {
  const char* text = dlerror();
  return text != nullptr ? text : "unknown error";
}

}  // namespace

std::shared_ptr<PluginLibrary> PluginLibrary::open(const std::filesystem::path& path) {
  dlerror();  // clear any stale error
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    throw PluginError("cannot open plugin library " + path.string() + ": " + last_dl_error());
  }
  using EntryFunction = const SwarmnetPluginEntry* (*)();
  void* symbol = dlsym(handle, kPluginEntrySymbol);
  if (symbol == nullptr) {
    const std::string error = last_dl_error();
    dlclose(handle);
    throw PluginError(path.string() + " is not a SwarmNet plugin: it exports no '" +
                      kPluginEntrySymbol + "' (" + error + ")");
  }
  const SwarmnetPluginEntry* entry = reinterpret_cast<EntryFunction>(symbol)();
  if (entry == nullptr || entry->descriptor == nullptr) {
    dlclose(handle);
    throw PluginError(path.string() + ": its entry returned no descriptor");
  }
  if (entry->abi_version != kAbiVersion) {
    const auto found = entry->abi_version;
    dlclose(handle);
    throw PluginError(path.string() + " was built against plugin ABI version " +
                      std::to_string(found) + ", but this SwarmNet has ABI version " +
                      std::to_string(kAbiVersion) + "; rebuild the plugin against this SDK");
  }
  const auto* descriptor = static_cast<const PluginDescriptor*>(entry->descriptor);
  // Owned from here: a table refused below closes the library on the way out.
  std::shared_ptr<PluginLibrary> library(new PluginLibrary(handle, descriptor, path));
  check_plugin_table(descriptor->info, path);
  return library;
}

PluginLibrary::~PluginLibrary() { dlclose(handle_); }

}  // namespace swarmnet
