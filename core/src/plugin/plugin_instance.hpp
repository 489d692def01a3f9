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

  PluginInstance(const PluginInstance&) = delete;
  PluginInstance& operator=(const PluginInstance&) = delete;
  PluginInstance(PluginInstance&&) noexcept = default;
  // By hand: the defaulted one would release the old library before destroying the old object,
  // unloading the code that object's destructor runs.
  PluginInstance& operator=(PluginInstance&& other) noexcept {
    object_ = std::move(other.object_);
    library_ = std::move(other.library_);
    return *this;
  }
  ~PluginInstance() = default;

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
