// One end of the channel between the robot half and the network half: an ordered, reliable
// stream of records in each direction. Every transport (in-process ring, shared-memory ring,
// Unix-domain socket, TCP) carries the same records, so every one gives the same results.
//
// Records are written and read in place: reserve() lends the caller the transport's own buffer
// (for a ring, the ring itself) to encode a record into, and receive_view() shows the next record
// where it lies, so a record's bytes are copied only where the channel itself must copy them.
#pragma once

#include <cstddef>
#include <cstring>
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

  // Lends `bytes` bytes of the channel's buffer for one record, waiting while the channel is
  // full; `space` is valid until commit() or the next reserve(). IoStatus::too_large when the
  // record can never fit.
  virtual IoStatus reserve(std::size_t bytes, std::span<std::byte>& space) = 0;
  // Sends the reserved record (visible to the peer at the latest at the next flush()).
  virtual IoStatus commit() = 0;
  // Sends one record and makes it visible only if that can be done now; never waits (for last
  // words on a failure path).
  virtual IoStatus try_send(std::span<const std::byte> record) = 0;
  // Makes every record sent so far visible to the peer. The step protocol calls it once per
  // batch, so a transport may gather records and make one system call per step.
  virtual IoStatus flush() = 0;
  // Shows the next record, waiting until one arrives. `record` is valid until the next receive
  // on this end (or release()); decode it before asking for another.
  virtual IoStatus receive_view(std::span<const std::byte>& record) = 0;
  // Done with the record receive_view() showed: its space may go back to the peer now.
  virtual void release() = 0;
  // No more sends: after draining, the peer's receive returns IoStatus::closed.
  virtual void close() = 0;
  // For logs and errors, e.g. "in-process ring, 1 MiB each way".
  [[nodiscard]] virtual std::string describe() const = 0;

  // Copying conveniences over the above: send a record held elsewhere; receive into a buffer.
  IoStatus send(std::span<const std::byte> record) {
    std::span<std::byte> space;
    const IoStatus status = reserve(record.size(), space);
    if (status != IoStatus::ok) return status;
    if (!record.empty()) std::memcpy(space.data(), record.data(), record.size());
    return commit();
  }
  IoStatus receive(std::vector<std::byte>& record) {
    std::span<const std::byte> view;
    const IoStatus status = receive_view(view);
    if (status != IoStatus::ok) return status;
    record.assign(view.begin(), view.end());
    release();
    return IoStatus::ok;
  }
};

}  // namespace swarmnet
