// A plugin object together with the library that made it: the library is released only after
// the object is destroyed, so its code outlives every object it created.
#pragma once

#include <memory>
#include <utility>

#include "plugin/plugin_library.hpp"
#include "swarmnet/plugin.hpp"

namespace swarmnet {

template <typename Interface>
class PluginInstance {
 public:
  PluginInstance() = default;
  PluginInstance(std::shared_ptr<PluginLibrary> library, std::unique_ptr<Plugin> object)
      : library_(std::move(library)), object_(std::move(object)) {}

  // Members are destroyed in reverse order: object_ first, then library_.
  Interface* get() const { return static_cast<Interface*>(object_.get()); }
  Interface* operator->() const { return get(); }
  Interface& operator*() const { return *get(); }
  explicit operator bool() const { return object_ != nullptr; }
  [[nodiscard]] const PluginLibrary& library() const { return *library_; }

 private:
  std::shared_ptr<PluginLibrary> library_;
  std::unique_ptr<Plugin> object_;
};

}  // namespace swarmnet
