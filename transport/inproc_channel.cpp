#include "inproc_channel.hpp"

#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>

namespace swarmnet {

void InprocChannel::AlignedFree::operator()(void* p) const { std::free(p); }

InprocChannel::InprocChannel(std::uint64_t ring_bytes, const WaitPolicy& policy)
    : InprocChannel(ring_bytes, policy, policy) {}

InprocChannel::InprocChannel(std::uint64_t ring_bytes, const WaitPolicy& robot_policy,
                             const WaitPolicy& network_policy)
    : ring_bytes_(ring_bytes) {
  const std::size_t one = SpscRing::footprint(ring_bytes);
  memory_.reset(std::aligned_alloc(kCacheLineBytes, 2 * one));
  if (!memory_) throw std::bad_alloc();
  auto* base = static_cast<std::byte*>(memory_.get());
  SpscRing to_network = SpscRing::create(base, ring_bytes);
  SpscRing to_robot = SpscRing::create(base + one, ring_bytes);
  const std::string description =
      "in-process ring, " + std::to_string(ring_bytes >> 10U) + " KiB each way";
  robot_end_ = std::make_unique<RingTransport>(to_network, to_robot, robot_policy, description);
  network_end_ = std::make_unique<RingTransport>(to_robot, to_network, network_policy, description);
}

}  // namespace swarmnet
