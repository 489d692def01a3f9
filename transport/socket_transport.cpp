#include "socket_transport.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

#include "transport_error.hpp"

namespace swarmnet {

namespace {

constexpr std::size_t kLengthBytes = 4;
constexpr std::size_t kFlushThreshold = std::size_t{1} << 20U;  // bound the send buffer

std::string system_error() { return std::strerror(errno); }

}  // namespace

SocketTransport::SocketTransport(int fd, WaitPolicy policy, std::string description)
    : fd_(fd), policy_(std::move(policy)), description_(std::move(description)) {
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) | O_NONBLOCK);
}

SocketTransport::~SocketTransport() {
  if (fd_ >= 0) ::close(fd_);
}

IoStatus SocketTransport::wait_for(short events) {
  // The same policy as the ring's (wait_policy.hpp): poll without sleeping while a spin pays
  // (wait_pace.hpp), yield a few times, then sleep in poll() in slices. A peer that answers
  // within microseconds then finds this side awake and its send() wakes nobody, as with the ring.
  pollfd p{fd_, events, 0};
  if (::poll(&p, 1, 0) > 0) return IoStatus::ok;
  const auto start = std::chrono::steady_clock::now();
  WaitPace& pace = events == POLLIN ? read_pace_ : write_pace_;
  const auto answered = [&] {
    pace.record(std::chrono::steady_clock::now() - start, policy_);
    return IoStatus::ok;
  };
  if (spin_then_yield(pace.plan(policy_, spinning_can_pay(start)), start,
                      [&] { return ::poll(&p, 1, 0) > 0; })) {
    return answered();
  }
  WaitDeadline deadline(policy_);
  const auto slice = std::chrono::duration_cast<std::chrono::milliseconds>(policy_.sleep_slice);
  for (;;) {
    const int ready = ::poll(&p, 1, static_cast<int>(std::max<std::int64_t>(1, slice.count())));
    if (ready > 0) return answered();
    if (ready < 0 && errno != EINTR) return IoStatus::closed;
    if (policy_.peer_alive && !policy_.peer_alive()) return IoStatus::peer_dead;
    // deadline_ (a handshake's) is a hard bound; the policy's yields to a peer that works.
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline_ || deadline.passed(now)) return IoStatus::timeout;
  }
}

IoStatus SocketTransport::reserve(std::size_t bytes, std::span<std::byte>& space) {
  if (write_closed_) return IoStatus::closed;
  if (bytes > kMaxRecordBytes) return IoStatus::too_large;
  const std::size_t end = out_end_ + kLengthBytes + bytes;
  // Grows geometrically, so the zero-filling of new space happens a few times per run.
  if (out_.size() < end) out_.resize(std::max(end, 2 * out_.size()));
  space = {out_.data() + out_end_ + kLengthBytes, bytes};
  reserved_bytes_ = bytes;
  reserved_ = true;
  return IoStatus::ok;
}

IoStatus SocketTransport::commit() {
  if (!reserved_) return IoStatus::ok;
  append_reserved();
  return out_end_ >= kFlushThreshold ? flush() : IoStatus::ok;
}

void SocketTransport::append_reserved() {
  const auto length = static_cast<std::uint32_t>(reserved_bytes_);
  std::memcpy(out_.data() + out_end_, &length, kLengthBytes);
  out_end_ += kLengthBytes + reserved_bytes_;
  reserved_ = false;
}

IoStatus SocketTransport::try_send(std::span<const std::byte> record) {
  // Appended without commit()'s flush, which may wait: this one never does.
  std::span<std::byte> space;
  const IoStatus status = reserve(record.size(), space);
  if (status != IoStatus::ok) return status;
  if (!record.empty()) std::memcpy(space.data(), record.data(), record.size());
  append_reserved();
  const ssize_t n = ::send(fd_, out_.data(), out_end_, MSG_NOSIGNAL | MSG_DONTWAIT);
  if (n > 0) {
    std::memmove(out_.data(), out_.data() + n, out_end_ - static_cast<std::size_t>(n));
    out_end_ -= static_cast<std::size_t>(n);
  }
  return out_end_ == 0 ? IoStatus::ok : IoStatus::would_block;
}

IoStatus SocketTransport::flush() {
  std::size_t done = 0;
  while (done < out_end_) {
    const ssize_t n = ::send(fd_, out_.data() + done, out_end_ - done, MSG_NOSIGNAL);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      if (const IoStatus s = wait_for(POLLOUT); s != IoStatus::ok) return s;
      continue;
    }
    return IoStatus::closed;  // EPIPE, ECONNRESET: the peer is gone
  }
  out_end_ = 0;
  return IoStatus::ok;
}

// Makes at least `bytes` unread bytes available in in_[in_start_, in_end_).
IoStatus SocketTransport::fill(std::size_t bytes) {
  if (in_end_ - in_start_ >= bytes) return IoStatus::ok;
  // More is needed: move what is left (at most a partial record, so this is cheap) to the front;
  // the buffer stays at about one record plus one read whatever the run's length.
  if (in_start_ != 0) {
    std::memmove(in_.data(), in_.data() + in_start_, in_end_ - in_start_);
    in_end_ -= in_start_;
    in_start_ = 0;
  }
  constexpr std::size_t kReadBytes = 65536;
  if (in_.size() < std::max(bytes, kReadBytes)) in_.resize(std::max(bytes, kReadBytes));
  while (in_end_ < bytes) {
    const ssize_t n = ::recv(fd_, in_.data() + in_end_, in_.size() - in_end_, 0);
    if (n > 0) {
      in_end_ += static_cast<std::size_t>(n);
      continue;
    }
    if (n == 0) return in_end_ == 0 ? IoStatus::closed : IoStatus::corrupt;
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) {
      if (std::chrono::steady_clock::now() >= deadline_) return IoStatus::timeout;
      if (const IoStatus s = wait_for(POLLIN); s != IoStatus::ok) return s;
      continue;
    }
    return IoStatus::closed;
  }
  return IoStatus::ok;
}

IoStatus SocketTransport::receive_view(std::span<const std::byte>& record) {
  if (const IoStatus s = fill(kLengthBytes); s != IoStatus::ok) return s;
  std::uint32_t length = 0;
  std::memcpy(&length, in_.data() + in_start_, kLengthBytes);
  if (length > max_record_bytes_) return IoStatus::corrupt;
  if (const IoStatus s = fill(kLengthBytes + length); s != IoStatus::ok) {
    return s == IoStatus::closed ? IoStatus::corrupt : s;  // cut off inside a record
  }
  record = {in_.data() + in_start_ + kLengthBytes, length};
  in_start_ += kLengthBytes + length;
  return IoStatus::ok;
}

void SocketTransport::close() {
  if (write_closed_) return;
  (void)flush();
  ::shutdown(fd_, SHUT_WR);
  write_closed_ = true;
}

namespace {

sockaddr_un unix_address(const std::string& path) {
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  if (path.size() >= sizeof(address.sun_path)) {
    throw TransportError("Unix socket path too long (" + std::to_string(path.size()) +
                         " bytes, at most " + std::to_string(sizeof(address.sun_path) - 1) +
                         "): " + path);
  }
  std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
  return address;
}

addrinfo* resolve(const std::string& host, std::uint16_t port, bool passive) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = passive ? AI_PASSIVE : 0;
  addrinfo* result = nullptr;
  const int rc = ::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &result);
  if (rc != 0) {
    throw TransportError("cannot resolve " + host + ":" + std::to_string(port) + ": " +
                         ::gai_strerror(rc));
  }
  return result;
}

void set_no_delay(int fd) {
  int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

}  // namespace

int listen_unix(const std::string& path) {
  const sockaddr_un address = unix_address(path);
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) throw TransportError("cannot create a Unix socket: " + system_error());
  if (::bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(fd, 1) != 0) {
    const std::string error = system_error();
    ::close(fd);
    throw TransportError("cannot listen on Unix socket " + path + ": " + error);
  }
  return fd;
}

int connect_unix(const std::string& path) {
  const sockaddr_un address = unix_address(path);
  const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) throw TransportError("cannot create a Unix socket: " + system_error());
  if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
    const std::string error = system_error();
    ::close(fd);
    throw TransportError("cannot connect to Unix socket " + path + ": " + error);
  }
  return fd;
}

int listen_tcp(const std::string& host, std::uint16_t port, std::uint16_t* bound_port,
               int backlog) {
  addrinfo* addresses = resolve(host, port, true);
  std::string error = "no address";
  int fd = -1;
  for (addrinfo* a = addresses; a != nullptr && fd < 0; a = a->ai_next) {
    fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    int one = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fd, a->ai_addr, a->ai_addrlen) != 0 || ::listen(fd, backlog) != 0) {
      error = system_error();
      ::close(fd);
      fd = -1;
    }
  }
  ::freeaddrinfo(addresses);
  if (fd < 0) {
    throw TransportError("cannot listen on " + host + ":" + std::to_string(port) + ": " + error);
  }
  if (bound_port != nullptr) {
    sockaddr_storage address{};
    socklen_t size = sizeof address;
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &size);
    *bound_port = address.ss_family == AF_INET6
                      ? ntohs(reinterpret_cast<sockaddr_in6*>(&address)->sin6_port)
                      : ntohs(reinterpret_cast<sockaddr_in*>(&address)->sin_port);
  }
  return fd;
}

int connect_tcp(const std::string& host, std::uint16_t port) {
  addrinfo* addresses = resolve(host, port, false);
  std::string error = "no address";
  int fd = -1;
  for (addrinfo* a = addresses; a != nullptr && fd < 0; a = a->ai_next) {
    fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    if (::connect(fd, a->ai_addr, a->ai_addrlen) != 0) {
      error = system_error();
      ::close(fd);
      fd = -1;
    }
  }
  ::freeaddrinfo(addresses);
  if (fd < 0) {
    throw TransportError("cannot connect to " + host + ":" + std::to_string(port) + ": " + error);
  }
  set_no_delay(fd);
  return fd;
}

int accept_next(int listener, const WaitPolicy& policy, const std::string& what,
                std::string* peer) {
  const auto deadline = std::chrono::steady_clock::now() + policy.timeout;
  for (;;) {
    pollfd p{listener, POLLIN, 0};
    const int ready = ::poll(&p, 1, 100);
    if (ready > 0) break;
    if (policy.peer_alive && !policy.peer_alive()) {
      throw TransportError("the peer died before connecting to " + what);
    }
    if (std::chrono::steady_clock::now() >= deadline) {
      throw TransportError("no connection on " + what + " within the timeout");
    }
  }
  sockaddr_storage remote{};
  socklen_t remote_size = sizeof remote;
  const int fd =
      ::accept4(listener, reinterpret_cast<sockaddr*>(&remote), &remote_size, SOCK_CLOEXEC);
  if (fd < 0) throw TransportError("cannot accept a connection on " + what + ": " + system_error());
  if (remote.ss_family != AF_UNIX) set_no_delay(fd);
  if (peer != nullptr) {
    char host[NI_MAXHOST] = "?";
    char port[NI_MAXSERV] = "?";
    if (remote.ss_family == AF_UNIX ||
        ::getnameinfo(reinterpret_cast<sockaddr*>(&remote), remote_size, host, sizeof host, port,
                      sizeof port, NI_NUMERICHOST | NI_NUMERICSERV) != 0) {
      *peer = what;
    } else {
      *peer = std::string(host) + ":" + port;
    }
  }
  return fd;
}

int accept_one(int listener, const WaitPolicy& policy, const std::string& what) {
  try {
    const int fd = accept_next(listener, policy, what);
    ::close(listener);
    return fd;
  } catch (...) {
    ::close(listener);
    throw;
  }
}

}  // namespace swarmnet
