// Neighbours a node has heard from recently (ns-3's aodv-neighbor): HELLOs and data traffic
// extend a neighbour's expiry; the MAC's report that a neighbour did not acknowledge a frame
// closes it at once. purge() removes expired and closed neighbours and reports each as a broken
// link, which the protocol turns into route invalidation and RERRs (RFC 3561 section 6.11).
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet::aodv {

class Neighbors {
 public:
  // Records that `neighbor` is alive until at least now + lifetime.
  void update(NodeId neighbor, SimTime lifetime, SimTime now);
  // The link to `neighbor` failed (no MAC acknowledgement): the next purge removes it.
  void close(NodeId neighbor);
  // Removes expired and closed neighbours; returns them (broken links), in id order.
  std::vector<NodeId> purge(SimTime now);

  [[nodiscard]] bool is_neighbor(NodeId node, SimTime now) const;
  // When `node` expires; kTimeZero if it is not a neighbour.
  [[nodiscard]] SimTime expiry(NodeId node) const;
  [[nodiscard]] std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    SimTime expires{};
    bool closed = false;
  };
  std::map<NodeId, Entry> entries_;
};

}  // namespace swarmnet::aodv
