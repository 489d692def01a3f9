// The run-wide counter that gives every packet (application or control) its uid.
#pragma once

#include <cstdint>

namespace swarmnet {

class PacketUidSource {
 public:
  // Uids start at 1 and increase by one per packet, in event order.
  std::uint64_t take() { return next_++; }
  [[nodiscard]] std::uint64_t issued() const { return next_ - 1; }

 private:
  std::uint64_t next_ = 1;
};

}  // namespace swarmnet
