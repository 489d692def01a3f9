// Errors found while locating, opening or instantiating a plugin.
#pragma once

#include <stdexcept>
#include <string>

namespace swarmnet {

class PluginError : public std::runtime_error {
 public:
  explicit PluginError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace swarmnet
