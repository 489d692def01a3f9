#include "coupling/handshake_acceptor.hpp"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <map>

#include "coupling/peer_authentication.hpp"
#include "transport_error.hpp"

namespace swarmnet {

namespace {

// "HOST:PORT" without its port (IPv6 hosts hold ':' too: the port follows the last one).
std::string host_of(const std::string& address) {
  const std::size_t colon = address.rfind(':');
  return colon == std::string::npos ? address : address.substr(0, colon);
}

}  // namespace

HandshakeAcceptor::HandshakeAcceptor(int listener, std::string where, PeerSecret secret,
                                     HandshakeSettings settings, void (*log)(const std::string&))
    : listener_(listener),
      where_(std::move(where)),
      secret_(std::move(secret)),
      settings_(std::move(settings)),
      log_(log),
      acceptor_([this] { accept_loop(); }) {}

HandshakeAcceptor::~HandshakeAcceptor() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
    for (Pending& p : pending_) {
      if (p.in_flight) ::shutdown(p.fd, SHUT_RDWR);
    }
  }
  acceptor_.join();
  // No thread is started any more: the list can be walked without the lock while they finish.
  for (Pending& p : pending_) p.thread.join();
  ::close(listener_);
}

std::size_t HandshakeAcceptor::pending() const {
  const std::lock_guard lock(mutex_);
  return static_cast<std::size_t>(std::count_if(pending_.begin(), pending_.end(),
                                                [](const Pending& p) { return p.in_flight; }));
}

std::optional<AuthenticatedPeer> HandshakeAcceptor::next(bool (*stopped)()) {
  std::unique_lock lock(mutex_);
  for (;;) {
    if (!ready_.empty()) {
      AuthenticatedPeer peer = std::move(ready_.front());
      ready_.pop_front();
      return peer;
    }
    if (listener_failed_ || (stopped != nullptr && stopped())) return std::nullopt;
    ready_changed_.wait_for(lock, std::chrono::milliseconds(100));
  }
}

void HandshakeAcceptor::accept_loop() {
  WaitPolicy at_once;  // the listener is readable when accept_next is called
  at_once.timeout = std::chrono::seconds(1);
  for (;;) {
    {
      const std::lock_guard lock(mutex_);
      if (stopping_) return;
      reap();
    }
    pollfd p{listener_, POLLIN, 0};
    const int ready = ::poll(&p, 1, 100);
    if (ready <= 0) continue;  // timeout or EINTR: look at stopping_ again
    if ((p.revents & (POLLERR | POLLNVAL)) != 0) {
      log_("the listener on " + where_ + " failed; no more robot halves are accepted");
      const std::lock_guard lock(mutex_);
      listener_failed_ = true;
      ready_changed_.notify_all();
      return;
    }
    std::string address;
    int fd = -1;
    try {
      fd = accept_next(listener_, at_once, where_, &address);
    } catch (const TransportError& error) {
      // Out of descriptors (EMFILE) and the like: the connection stays queued; try again soon.
      log_(std::string("cannot accept on ") + where_ + ": " + error.what());
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      continue;
    }
    const std::lock_guard lock(mutex_);
    if (stopping_) {
      ::close(fd);
      return;
    }
    const auto in_flight = static_cast<std::uint32_t>(std::count_if(
        pending_.begin(), pending_.end(), [](const Pending& q) { return q.in_flight; }));
    if (in_flight >= settings_.max_pending) evict_one();
    Pending& added = pending_.emplace_back();
    added.fd = fd;
    added.address = address;
    added.host = host_of(address);
    added.accepted = std::chrono::steady_clock::now();
    added.thread = std::thread([this, &added] { handshake(&added); });
  }
}

void HandshakeAcceptor::handshake(Pending* pending) {
  auto transport = std::make_unique<SocketTransport>(pending->fd, settings_.policy,
                                                     "TCP from " + pending->address);
  transport->set_max_record_bytes(settings_.max_record_bytes);
  transport->set_deadline(pending->accepted + settings_.deadline);
  const std::string why = authenticate_connector(*transport, secret_);
  const std::lock_guard lock(mutex_);
  // Evicted after its last record arrived: the connection is shut down, so it is not handed out.
  const bool evicted = !pending->in_flight;
  pending->in_flight = false;  // from here on nobody shuts the descriptor down
  pending->finished = true;
  if (why.empty() && evicted) return;
  if (!why.empty()) {
    log_("refused " + pending->address + ": " + why);
    return;  // the transport closes the connection
  }
  if (stopping_) return;
  ready_.push_back(AuthenticatedPeer{std::move(transport), pending->address});
  ready_changed_.notify_all();
}

void HandshakeAcceptor::evict_one() {
  std::map<std::string, std::uint32_t> per_host;
  for (const Pending& p : pending_) {
    if (p.in_flight) ++per_host[p.host];
  }
  const auto busiest =
      std::max_element(per_host.begin(), per_host.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; });
  for (Pending& p : pending_) {  // oldest first
    if (p.in_flight && p.host == busiest->first) {
      log_("dropped " + p.address + ": " + std::to_string(settings_.max_pending) +
           " handshakes were pending (" + std::to_string(busiest->second) + " from " + p.host +
           ") and another peer connected");
      ::shutdown(p.fd, SHUT_RDWR);  // its thread sees the connection end and finishes
      p.in_flight = false;          // no longer counted; never shut down twice
      return;
    }
  }
}

void HandshakeAcceptor::reap() {
  for (auto it = pending_.begin(); it != pending_.end();) {
    if (!it->finished) {
      ++it;
      continue;
    }
    it->thread.join();  // it only closes its connection after `finished`; it takes no lock
    it = pending_.erase(it);
  }
}

}  // namespace swarmnet
