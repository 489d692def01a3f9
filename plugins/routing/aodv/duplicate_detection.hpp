// Duplicate detection for broadcast data (ns-3's aodv-dpd): a rebroadcast application packet is
// recognised by its originator and uid, which every copy keeps.
#pragma once

#include "id_cache.hpp"
#include "swarmnet/packet.hpp"

namespace swarmnet::aodv {

class DuplicateDetection {
 public:
  explicit DuplicateDetection(SimTime lifetime) : cache_(lifetime) {}

  // True if this packet was seen in the last `lifetime`; otherwise remembers it.
  bool is_duplicate(const Packet& packet, SimTime now) {
    return cache_.is_duplicate(packet.source, packet.uid, now);
  }
  [[nodiscard]] std::size_t size() const { return cache_.size(); }

 private:
  IdCache cache_;
};

}  // namespace swarmnet::aodv
