// Neighbours a node has heard from recently (ns-3's aodv-neighbor): HELLOs, new RREQs and data
// traffic extend a neighbour's expiry; the MAC's report that it dropped a frame to a neighbour
// closes it at once. purge() removes expired and closed neighbours and reports each as a broken
// link, which the protocol turns into route invalidation and RERRs (RFC 3561 section 6.11).
//
// As in ns-3, a neighbour carries its link-layer address only if the node's ARP cache resolved
// it when the neighbour was recorded or refreshed (Neighbors::Update, LookupMacAddress); ns-3
// matches a dropped MPDU to neighbours by that address (ProcessTxError), so a neighbour whose
// address was never resolved cannot be closed by the MAC. Once known, the address is kept.
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet::aodv {

class Neighbors {
 public:
  // Records that `neighbor` is alive until at least now + lifetime. `address_known`: the ARP
  // cache resolves it now (consulted by ns-3 only while the address is still unknown). Returns
  // true if `neighbor` was not a neighbour (ns-3 then purges the list).
  bool update(NodeId neighbor, SimTime lifetime, SimTime now, bool address_known = true);
  // The link to `neighbor` failed: the next purge removes it, whether or not its address is
  // known (SwarmNet's rule before ns-3's matching, link_failure_match: next_hop).
  void close(NodeId neighbor);
  // ns-3's ProcessTxError for an MPDU sent to `neighbor`: closes it only if it is listed with a
  // known link-layer address. Returns whether it did.
  bool close_by_address(NodeId neighbor);
  // Removes expired and closed neighbours; returns them (broken links), in id order.
  std::vector<NodeId> purge(SimTime now);

  [[nodiscard]] bool is_neighbor(NodeId node, SimTime now) const;
  // Whether `node` is listed with a known link-layer address.
  [[nodiscard]] bool address_known(NodeId node) const;
  // When `node` expires; kTimeZero if it is not a neighbour.
  [[nodiscard]] SimTime expiry(NodeId node) const;
  [[nodiscard]] std::size_t size() const { return entries_.size(); }
  [[nodiscard]] bool empty() const { return entries_.empty(); }

 private:
  struct Entry {
    SimTime expires{};
    bool address_known = false;
    bool closed = false;
  };
  std::map<NodeId, Entry> entries_;
};

}  // namespace swarmnet::aodv
