// One end of the channel between the robot half and the network half: an ordered, reliable
// stream of records in each direction. Every transport (in-process ring, shared-memory ring,
// Unix-domain socket, TCP) carries the same records, so every one gives the same results.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "ring_status.hpp"

namespace swarmnet {

class Transport {
 public:
  Transport() = default;
  Transport(const Transport&) = delete;
  Transport& operator=(const Transport&) = delete;
  Transport(Transport&&) = delete;
  Transport& operator=(Transport&&) = delete;
  virtual ~Transport() = default;

  // Sends one record, waiting while the channel is full.
  virtual IoStatus send(std::span<const std::byte> record) = 0;
  // Sends one record and makes it visible only if that can be done now; never waits (for last
  // words on a failure path).
  virtual IoStatus try_send(std::span<const std::byte> record) = 0;
  // Makes every record sent so far visible to the peer. The step protocol calls it once per
  // batch, so a transport may gather records and make one system call per step.
  virtual IoStatus flush() = 0;
  // Receives the next record, waiting until one arrives.
  virtual IoStatus receive(std::vector<std::byte>& record) = 0;
  // No more sends: after draining, the peer's receive() returns IoStatus::closed.
  virtual void close() = 0;
  // For logs and errors, e.g. "in-process ring, 1 MiB each way".
  [[nodiscard]] virtual std::string describe() const = 0;
};

}  // namespace swarmnet
