// A run that cannot go on: the message says what failed and where.
#pragma once

#include <stdexcept>
#include <string>

namespace swarmnet {

class RunError : public std::runtime_error {
 public:
  explicit RunError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace swarmnet
