#include "ns3_host/ns3_engine_library.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>

#include "plugin/executable_layout.hpp"

namespace swarmnet {

namespace {

constexpr const char* kModuleFile = "libswarmnet_ns3_engine.so";

using ApiVersionFunction = std::uint32_t (*)();
using CreateFunction = ns3engine::Network* (*)(const ns3engine::Config&);

struct LoadedModule {
  CreateFunction create = nullptr;
  std::string error;  // why it could not be loaded (then create is null)
};

LoadedModule load(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    return {nullptr, path.string() +
                         " does not exist: this SwarmNet was built without ns-3 (./swarmnet "
                         "install ns3 installs libns3-dev, and the next ./swarmnet command "
                         "builds the engine; built by hand: install libns3-dev, configure "
                         "again and rebuild)"};
  }
  // Never closed (see the header): the handle lives as long as the process.
  void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) return {nullptr, "cannot load " + path.string() + ": " + ::dlerror()};
  auto version =
      reinterpret_cast<ApiVersionFunction>(::dlsym(handle, "swarmnet_ns3_engine_api_version"));
  auto create = reinterpret_cast<CreateFunction>(::dlsym(handle, "swarmnet_ns3_engine_create"));
  if (version == nullptr || create == nullptr) {
    return {nullptr, path.string() + " is not SwarmNet's ns-3 engine module (no entry points)"};
  }
  if (version() != ns3engine::kApiVersion) {
    return {nullptr, path.string() + " speaks engine API " + std::to_string(version()) +
                         ", this swarmnet " + std::to_string(ns3engine::kApiVersion) +
                         ": rebuild them together"};
  }
  return {create, ""};
}

}  // namespace

std::filesystem::path ns3_engine_module_path() {
  if (const char* path = std::getenv("SWARMNET_NS3_ENGINE"); path != nullptr && *path != '\0') {
    return path;
  }
  return executable_layout().engine_dir / kModuleFile;
}

std::unique_ptr<ns3engine::Network> create_ns3_network(const ns3engine::Config& config) {
  static std::once_flag once;
  static LoadedModule module;
  std::call_once(once, [] { module = load(ns3_engine_module_path()); });
  if (module.create == nullptr) throw std::runtime_error("ns-3 engine: " + module.error);
  return std::unique_ptr<ns3engine::Network>(module.create(config));
}

}  // namespace swarmnet
