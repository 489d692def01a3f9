// A Transport over two SpscRings: one this end produces into, one it consumes from. Where the
// rings live (heap memory shared by two threads, or a shared-memory segment shared by two
// processes) is the owner's business. Records are encoded straight into the outgoing ring and
// decoded straight out of the incoming one.
#pragma once

#include <string>

#include "spsc_ring.hpp"
#include "transport.hpp"
#include "wait_policy.hpp"

namespace swarmnet {

class RingTransport final : public Transport {
 public:
  RingTransport(SpscRing outgoing, SpscRing incoming, WaitPolicy policy, std::string description)
      : outgoing_(outgoing),
        incoming_(incoming),
        policy_(std::move(policy)),
        description_(std::move(description)) {}

  // Records are staged and shown to the peer together at flush(), once per batch.
  IoStatus reserve(std::size_t bytes, std::span<std::byte>& space) override {
    return outgoing_.reserve(bytes, space, policy_);
  }
  IoStatus commit() override {
    outgoing_.commit();
    return IoStatus::ok;
  }
  IoStatus try_send(std::span<const std::byte> record) override {
    return outgoing_.try_push(record);
  }
  IoStatus flush() override {
    outgoing_.publish();
    return IoStatus::ok;
  }
  IoStatus receive_view(std::span<const std::byte>& record) override {
    return incoming_.read(record, policy_);
  }
  void release() override { incoming_.release(); }
  void close() override {
    outgoing_.close_producer();
    incoming_.close_consumer();
  }
  [[nodiscard]] std::string describe() const override { return description_; }

 private:
  SpscRing outgoing_;
  SpscRing incoming_;
  WaitPolicy policy_;
  std::string description_;
};

}  // namespace swarmnet
