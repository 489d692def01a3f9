// A transmitter's receivers as the channel computes them for a frame (or for every frame of a
// step when links are reused): one link per receiver that gets the frame at all, in arrival order.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "swarmnet/ids.hpp"
#include "swarmnet/units.hpp"

namespace swarmnet {

class Phy;

struct ChannelLink {
  SimTime delay;
  NodeId receiver;
  bool far;  // is_far_signal: the receiver gets it as a FarSignal, not as events (far_signals.hpp)
  Phy* phy;  // the receiver's, kept beside the link: one cache line per receiver, not two
  double power_dbm;
  double power_mw;
  std::int64_t far_units;  // far links: power_mw in the far-signal bookkeeping's units, rounded up
};

// A far link as the far-signal bookkeeping walks it at every frame sent and retired: the
// receiver, the link's index and its units side by side, so that the walk reads one 16-byte
// entry per receiver instead of the receiver's 48-byte link.
struct FarLink {
  NodeId receiver;
  std::uint32_t link;
  std::int64_t units;  // the link's far_units
};

// ChannelLinks::index_far's working space, kept by whoever indexes many link sets (the channel,
// whose arrival sort uses link_of_receiver too), so that link sets, shared while their frames are
// on the air, do not carry it.
struct FarIndexScratch {
  explicit FarIndexScratch(std::size_t nodes) : link_of_receiver(nodes) {}
  std::vector<std::uint32_t> link_of_receiver;  // per receiver: any content, left changed
  std::vector<std::uint64_t> has_far_link;      // one bit per receiver
};

struct ChannelLinks {
  std::vector<ChannelLink> links;  // by (delay, receiver): arrival order
  // The far links by receiver, ascending (the order in which the far-signal bookkeeping visits
  // receivers, so the order of what it hands over).
  std::vector<FarLink> far_by_receiver;
  // The links that are not far, by index in arrival order: the fan-out's two streams walk these
  // (about 9 of 190 links in the study's scenario) instead of skipping the far ones one by one.
  std::vector<std::uint32_t> near;

  void clear() {
    links.clear();
    far_by_receiver.clear();
    near.clear();
  }
  // Fills `near` from links.
  void index_near() {
    near.clear();
    for (std::uint32_t i = 0; i < links.size(); ++i) {
      if (!links[i].far) near.push_back(i);
    }
  }
  // Fills the far-link index from links, for receivers numbered below `scratch`'s node count.
  void index_far(FarIndexScratch& scratch) {
    std::vector<std::uint64_t>& has_far = scratch.has_far_link;
    has_far.assign((scratch.link_of_receiver.size() + 63) / 64, 0);
    for (std::uint32_t i = 0; i < links.size(); ++i) {
      if (!links[i].far) continue;
      has_far[links[i].receiver / 64] |= bit(links[i].receiver);
      scratch.link_of_receiver[links[i].receiver] = i;
    }
    // In receiver order, by walking the bits.
    far_by_receiver.clear();
    for (std::size_t w = 0; w < has_far.size(); ++w) {
      for (std::uint64_t bits = has_far[w]; bits != 0; bits &= bits - 1) {
        const auto receiver = static_cast<NodeId>(w * 64 + std::countr_zero(bits));
        const std::uint32_t link = scratch.link_of_receiver[receiver];
        far_by_receiver.push_back(FarLink{receiver, link, links[link].far_units});
      }
    }
  }

 private:
  static std::uint64_t bit(NodeId receiver) { return std::uint64_t{1} << (receiver % 64); }
};

}  // namespace swarmnet
