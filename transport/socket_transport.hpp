// A Transport over a connected stream socket (Unix-domain or TCP): records are framed as a
// 4-byte little-endian length and the bytes, encoded in place into a buffer and written with one
// system call per flush (once per step), not one per record; received records are shown where
// they lie in the receive buffer.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "transport.hpp"
#include "wait_pace.hpp"
#include "wait_policy.hpp"

namespace swarmnet {

class SocketTransport final : public Transport {
 public:
  // Takes ownership of the connected socket `fd`.
  SocketTransport(int fd, WaitPolicy policy, std::string description);
  ~SocketTransport() override;

  IoStatus reserve(std::size_t bytes, std::span<std::byte>& space) override;
  IoStatus commit() override;
  IoStatus try_send(std::span<const std::byte> record) override;
  IoStatus flush() override;
  IoStatus receive_view(std::span<const std::byte>& record) override;
  void release() override {}  // the receive buffer is reused at the next receive
  void close() override;
  [[nodiscard]] std::string describe() const override { return description_; }

  // Largest record accepted from the peer by default; a longer announced length is corrupt
  // framing.
  static constexpr std::uint32_t kMaxRecordBytes = 1U << 26U;

  // A server meeting an unknown peer narrows what it accepts until the peer is known: a smaller
  // largest record (nothing longer is buffered), and an absolute deadline by which every receive
  // must have completed (a peer that trickles bytes cannot hold it). Then it widens them again.
  void set_max_record_bytes(std::uint32_t bytes) { max_record_bytes_ = bytes; }
  void set_deadline(std::chrono::steady_clock::time_point deadline) { deadline_ = deadline; }
  void clear_deadline() { deadline_ = std::chrono::steady_clock::time_point::max(); }

 private:
  IoStatus wait_for(short events);
  IoStatus fill(std::size_t bytes);
  // Puts the reserved record's length before it and counts it as waiting to be sent.
  void append_reserved();

  int fd_;
  WaitPolicy policy_;
  WaitPace read_pace_;  // how quickly the peer lately answered waits to read, and to write
  WaitPace write_pace_;
  std::string description_;
  // Both buffers only grow (their unused tails are never zero-filled again): out_[0, out_end_)
  // waits to be sent, in_[in_start_, in_end_) has been received and not yet shown.
  std::vector<std::byte> out_;
  std::size_t out_end_ = 0;
  std::size_t reserved_bytes_ = 0;
  bool reserved_ = false;
  std::vector<std::byte> in_;
  std::size_t in_start_ = 0;
  std::size_t in_end_ = 0;
  bool write_closed_ = false;
  std::uint32_t max_record_bytes_ = kMaxRecordBytes;
  std::chrono::steady_clock::time_point deadline_ = std::chrono::steady_clock::time_point::max();
};

// Connection set-up; each throws TransportError naming the address and the system's reason.
int listen_unix(const std::string& path);  // bound, listening socket
int connect_unix(const std::string& path);
// `backlog`: connections the kernel queues before accept (a server meeting many peers wants more
// than the one a run's own child needs).
int listen_tcp(const std::string& host, std::uint16_t port, std::uint16_t* bound_port = nullptr,
               int backlog = 1);
int connect_tcp(const std::string& host, std::uint16_t port);
// Waits up to `policy.timeout` for one connection on `listener`, then closes the listener.
int accept_one(int listener, const WaitPolicy& policy, const std::string& what);
// Waits up to `policy.timeout` for the next connection on `listener`, which stays open; fills
// `peer` with the peer's address ("127.0.0.1:40112") when given.
int accept_next(int listener, const WaitPolicy& policy, const std::string& what,
                std::string* peer = nullptr);

}  // namespace swarmnet
