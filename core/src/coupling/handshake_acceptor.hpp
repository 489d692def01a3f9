// The front door of `swarmnet net --listen`: accepts connections and runs each one's challenge
// and response (peer_authentication.hpp) in a thread of its own, each under its own deadline, so
// that silent or slow peers cannot keep a real robot half waiting behind them. At most
// `max_pending` handshakes are in flight; a connection arriving when that many are pending
// evicts the oldest pending one from the address holding the most (a flood from one host loses
// its own oldest first). Peers that authenticate wait, in the order they did, until the server
// takes them with next().
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <list>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "coupling/peer_secret.hpp"
#include "socket_transport.hpp"

namespace swarmnet {

struct HandshakeSettings {
  std::chrono::milliseconds deadline{std::chrono::seconds(5)};  // per connection, from accept
  std::uint32_t max_pending = 64;                               // handshakes in flight
  std::uint32_t max_record_bytes = 1U << 16U;                   // until the hello is read
  WaitPolicy policy;  // the authenticated transport's (step timeout, stop check)
};

// A peer that proved it knows the token: its transport, still under the handshake's small
// record limit (the server widens it once the hello is read), and its address.
struct AuthenticatedPeer {
  std::unique_ptr<SocketTransport> transport;
  std::string address;
};

class HandshakeAcceptor {
 public:
  // Serves `listener` (owned, closed on destruction), described as `where` in messages. Each
  // refusal and eviction is written to `log` (one line each).
  HandshakeAcceptor(int listener, std::string where, PeerSecret secret, HandshakeSettings settings,
                    void (*log)(const std::string&));
  HandshakeAcceptor(const HandshakeAcceptor&) = delete;
  HandshakeAcceptor& operator=(const HandshakeAcceptor&) = delete;
  HandshakeAcceptor(HandshakeAcceptor&&) = delete;
  HandshakeAcceptor& operator=(HandshakeAcceptor&&) = delete;
  // Stops accepting, ends every pending handshake and joins every thread.
  ~HandshakeAcceptor();

  // The next authenticated peer; waits for one. nullopt once `stopped()` answers true (polled
  // every 100 ms), or when the listener failed (the reason went to the log).
  std::optional<AuthenticatedPeer> next(bool (*stopped)());

  // Handshakes in flight now (for tests and the log).
  [[nodiscard]] std::size_t pending() const;

 private:
  struct Pending {
    int fd = -1;  // shut down, never closed, by the acceptor: its thread's transport owns it
    std::string address;
    std::string host;  // the address without its port, for eviction
    std::chrono::steady_clock::time_point accepted;
    bool in_flight = true;  // false once evicted or finished: counted against max_pending
    bool finished = false;  // its thread is past its last use of this entry
    std::thread thread;
  };

  void accept_loop();
  void handshake(Pending* pending);
  void evict_one();  // with mutex_ held
  void reap();       // with mutex_ held: joins finished handshakes and forgets them

  const int listener_;
  const std::string where_;
  const PeerSecret secret_;
  const HandshakeSettings settings_;
  void (*const log_)(const std::string&);

  mutable std::mutex mutex_;
  std::condition_variable ready_changed_;
  std::list<Pending> pending_;  // oldest first; stable addresses for the threads
  std::deque<AuthenticatedPeer> ready_;
  bool stopping_ = false;
  bool listener_failed_ = false;
  std::thread acceptor_;
};

}  // namespace swarmnet
