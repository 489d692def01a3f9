// Two RingTransports joined by a pair of rings in one heap block: the transport for running
// both halves as threads of one process.
#pragma once

#include <cstdint>
#include <memory>

#include "ring_transport.hpp"

namespace swarmnet {

class InprocChannel {
 public:
  // `ring_bytes`: storage of each ring, a power of two.
  explicit InprocChannel(std::uint64_t ring_bytes = std::uint64_t{1} << 20,
                         const WaitPolicy& policy = {});
  // Each end waits under its own policy (the two halves are different threads: each end's
  // peer_cpu reads the other half's thread).
  InprocChannel(std::uint64_t ring_bytes, const WaitPolicy& robot_policy,
                const WaitPolicy& network_policy);

  [[nodiscard]] std::uint64_t ring_bytes() const { return ring_bytes_; }
  RingTransport& robot_end() { return *robot_end_; }
  RingTransport& network_end() { return *network_end_; }

 private:
  struct AlignedFree {
    void operator()(void* p) const;
  };
  std::uint64_t ring_bytes_;
  std::unique_ptr<void, AlignedFree> memory_;
  std::unique_ptr<RingTransport> robot_end_;
  std::unique_ptr<RingTransport> network_end_;
};

}  // namespace swarmnet
