// Setting up a transport failed (segment, socket, handshake): the message says what and where.
#pragma once

#include <stdexcept>
#include <string>

namespace swarmnet {

class TransportError : public std::runtime_error {
 public:
  explicit TransportError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace swarmnet
