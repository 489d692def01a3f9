#include "coupling/network_link.hpp"

#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <thread>

#include "coupling/child_process.hpp"
#include "coupling/network_half.hpp"
#include "coupling/peer_authentication.hpp"
#include "coupling/peer_cpu.hpp"
#include "coupling/socket_directory.hpp"
#include "coupling/stop_signal.hpp"
#include "inproc_channel.hpp"
#include "outputs/run_error.hpp"
#include "protocol/step_channel.hpp"
#include "ring_transport.hpp"
#include "scenario/shown_value.hpp"
#include "shm_segment.hpp"
#include "socket_transport.hpp"
#include "transport_error.hpp"

namespace swarmnet {

const char* to_string(TransportKind kind) {
  switch (kind) {
    case TransportKind::shm:
      return "shm";
    case TransportKind::inproc:
      return "inproc";
    case TransportKind::uds:
      return "uds";
    case TransportKind::tcp:
      return "tcp";
  }
  return "?";
}

std::optional<TransportKind> parse_transport_kind(std::string_view text) {
  for (TransportKind kind :
       {TransportKind::shm, TransportKind::inproc, TransportKind::uds, TransportKind::tcp}) {
    if (text == to_string(kind)) return kind;
  }
  return std::nullopt;
}

namespace {

// How long a network half may take to stop after the robot half closed its end.
constexpr std::chrono::milliseconds kStopGrace{2000};

// `child`: the network half's process, when this half started it. Its CPU time then tells a
// long step from a hang: the step timeout counts only time in which the child did not compute.
// A remote half has no process of ours to look at: the timeout is a fixed bound. (An in-process
// half is a thread: InprocLink reads its CPU clock.)
WaitPolicy policy_with(const LinkOptions& options, ChildProcess* child) {
  WaitPolicy policy;
  policy.timeout = options.step_timeout;
  policy.peer_alive = [child] {
    return stop_signal() == 0 && (child == nullptr || child->alive());
  };
  if (child != nullptr) {
    policy.peer_cpu = [pid = child->pid()] { return process_cpu_time(pid); };
  }
  return policy;
}

std::string mib(std::uint64_t bytes) { return std::to_string(bytes >> 20U) + " MiB"; }

// Both halves as threads of this process over heap rings.
class InprocLink final : public NetworkLink {
 public:
  // The robot half has created everything it needs from `loader` before the link opens, so the
  // network thread, started after that, is the loader's only user from then on.
  InprocLink(const Scenario& scenario, PluginLoader& loader, const std::filesystem::path& run_dir,
             const LinkOptions& options)
      : channel_(options.ring_bytes, robot_end_policy(options), network_end_policy(options)),
        network_channel_(channel_.network_end(), "the robot half") {
    thread_ = std::thread([this, &scenario, &loader, run_dir] {
      network_tid_.store(static_cast<pid_t>(::syscall(SYS_gettid)));
      try {
        serve_network_connection(network_channel_, [&](const Hello&) {
          // The robot half's own validated scenario and loader: nothing is resolved twice.
          return NetworkSetup{scenario, run_dir, &loader, nullptr};
        });
      } catch (const std::exception& error) {
        error_ = error.what();
      }
    });
  }
  ~InprocLink() override {
    if (thread_.joinable()) {
      channel_.robot_end().close();
      thread_.join();
    }
  }
  Transport& transport() override { return channel_.robot_end(); }
  [[nodiscard]] std::string describe() const override {
    return "in-process rings, " + mib(channel_.ring_bytes()) + " each way";
  }
  [[nodiscard]] pid_t local_network_pid() const override { return ::getpid(); }
  // Set by the thread as it starts, long before the handshake it answers is over.
  [[nodiscard]] ThreadId network_thread() const override {
    return {::getpid(), network_tid_.load()};
  }
  std::string finish() override {
    thread_.join();
    return error_;
  }

 private:
  // A step that takes the network thread longer than the step timeout is slow, not hung, while
  // that thread computes: the robot end reads its CPU clock, as it reads a child's CPU time. Only
  // the robot half's thread waits on this end, and it also starts and joins thread_.
  WaitPolicy robot_end_policy(const LinkOptions& options) {
    WaitPolicy policy = policy_with(options, nullptr);
    policy.peer_cpu = [this]() -> std::chrono::nanoseconds {
      if (!thread_.joinable()) return {};  // not started yet, or joined
      return thread_cpu_time(thread_.native_handle());
    };
    return policy;
  }
  // Likewise the network end for the robot half: the thread that opens the link runs it.
  static WaitPolicy network_end_policy(const LinkOptions& options) {
    WaitPolicy policy = policy_with(options, nullptr);
    policy.peer_cpu = [robot = pthread_self()] { return thread_cpu_time(robot); };
    return policy;
  }

  InprocChannel channel_;
  StepChannel network_channel_;
  std::thread thread_;
  std::atomic<pid_t> network_tid_{0};
  std::string error_;
};

// A child `swarmnet net` process over any transport.
class ChildLink final : public NetworkLink {
 public:
  ChildLink(std::unique_ptr<ChildProcess> child, std::unique_ptr<Transport> transport,
            std::unique_ptr<ShmSegment> segment, std::string description)
      : child_(std::move(child)),
        transport_(std::move(transport)),
        segment_(std::move(segment)),
        description_(std::move(description)) {}
  Transport& transport() override { return *transport_; }
  [[nodiscard]] std::string describe() const override {
    return description_ + ", network half pid " + std::to_string(child_->pid());
  }
  [[nodiscard]] pid_t local_network_pid() const override { return child_->pid(); }
  // `swarmnet net` serves the run on its main thread.
  [[nodiscard]] ThreadId network_thread() const override { return {child_->pid(), child_->pid()}; }
  void connected() override {
    if (segment_) segment_->remove_name();
  }
  std::string finish() override {
    const std::string how = child_->wait(kStopGrace);
    if (segment_) segment_->remove_name();
    return how.empty() ? "" : "the network half (pid " + std::to_string(child_->pid()) + ") " + how;
  }

 private:
  std::unique_ptr<ChildProcess> child_;
  std::unique_ptr<Transport> transport_;
  std::unique_ptr<ShmSegment> segment_;
  std::string description_;
};

// A network half started elsewhere (`swarmnet net --listen`).
class RemoteLink final : public NetworkLink {
 public:
  RemoteLink(std::unique_ptr<Transport> transport, std::string description)
      : transport_(std::move(transport)), description_(std::move(description)) {}
  Transport& transport() override { return *transport_; }
  [[nodiscard]] std::string describe() const override { return description_; }
  [[nodiscard]] pid_t local_network_pid() const override { return 0; }
  [[nodiscard]] ThreadId network_thread() const override { return {}; }
  std::string finish() override { return ""; }

 private:
  std::unique_ptr<Transport> transport_;
  std::string description_;
};

std::pair<std::string, std::uint16_t> split_host_port(const std::string& text) {
  const auto colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size()) {
    throw RunError("'" + text + "' is not HOST:PORT");
  }
  const std::string port_text = text.substr(colon + 1);
  char* end = nullptr;
  const long port = std::strtol(port_text.c_str(), &end, 10);
  if (*end != '\0' || port < 0 || port > 65535) throw RunError("bad port in '" + text + "'");
  std::string host = text.substr(0, colon);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']')
    host = host.substr(1, host.size() - 2);
  return {host, static_cast<std::uint16_t>(port)};
}

std::vector<std::string> child_arguments(const LinkOptions& options, const std::string& flag,
                                         const std::string& address) {
  return {"net",
          flag,
          address,
          "--parent",
          std::to_string(::getpid()),
          "--step-timeout-ms",
          std::to_string(options.step_timeout.count())};
}

// A socket child learns this run's one-time secret from its environment, which only this user
// can read; whoever connects must prove it knows it (another local user could connect first).
std::vector<std::string> child_environment(const PeerSecret& secret) {
  return {std::string(kChildSecretVariable) + "=" + secret.hex()};
}

void check_child(Transport& transport, const PeerSecret& secret, const std::string& address) {
  if (std::string why = authenticate_connector(transport, secret); !why.empty()) {
    throw RunError("the process that connected to " + address +
                   " is not the network half this run started: " + why);
  }
}

}  // namespace

std::pair<std::string, std::uint16_t> parse_host_port(const std::string& text) {
  return split_host_port(text);
}

std::unique_ptr<NetworkLink> open_network_link(const Scenario& scenario, PluginLoader& loader,
                                               const std::filesystem::path& run_dir,
                                               const LinkOptions& options) {
  if (!options.remote.empty()) {
    const std::string prefix = "tcp://";
    if (!options.remote.starts_with(prefix)) {
      throw RunError("--net takes tcp://HOST:PORT, not '" + shown_value(options.remote) + "'");
    }
    const auto [host, port] = split_host_port(options.remote.substr(prefix.size()));
    const std::filesystem::path token = token_file_from(options.token_file);
    if (token.empty()) {
      throw RunError(std::string("--net needs the token the network half was started with: ") +
                     "--token-file FILE or " + kTokenFileVariable + " (docs/security.md)");
    }
    const PeerSecret secret = PeerSecret::from_file(token);
    auto transport = std::make_unique<SocketTransport>(connect_tcp(host, port),
                                                       policy_with(options, nullptr), "TCP");
    if (std::string why = authenticate_to_acceptor(*transport, secret); !why.empty()) {
      throw RunError(options.remote + ": " + why);
    }
    return std::make_unique<RemoteLink>(std::move(transport), "TCP to " + options.remote);
  }
  switch (options.kind) {
    case TransportKind::inproc:
      return std::make_unique<InprocLink>(scenario, loader, run_dir, options);
    case TransportKind::shm: {
      auto segment = ShmSegment::create(options.ring_bytes);
      auto child =
          std::make_unique<ChildProcess>(child_arguments(options, "--shm", segment->name()));
      ChildProcess* watched = child.get();
      auto transport =
          std::make_unique<RingTransport>(segment->robot_to_network(), segment->network_to_robot(),
                                          policy_with(options, watched), "shared memory");
      const std::string description = "shared-memory rings /dev/shm/" + segment->name() + ", " +
                                      mib(options.ring_bytes) + " each way";
      return std::make_unique<ChildLink>(std::move(child), std::move(transport), std::move(segment),
                                         description);
    }
    case TransportKind::uds: {
      SocketDirectory directory;
      const std::string path = (directory.path() / "network.sock").string();
      const int listener = listen_unix(path);
      const PeerSecret secret = PeerSecret::random();
      auto child = std::make_unique<ChildProcess>(child_arguments(options, "--uds", path),
                                                  child_environment(secret));
      ChildProcess* watched = child.get();
      const WaitPolicy policy = policy_with(options, watched);
      const int fd = accept_one(listener, policy, "Unix socket " + path);
      auto transport = std::make_unique<SocketTransport>(fd, policy, "Unix-domain socket");
      check_child(*transport, secret, path);
      return std::make_unique<ChildLink>(std::move(child), std::move(transport), nullptr,
                                         "Unix-domain socket");
    }
    case TransportKind::tcp: {
      std::uint16_t port = 0;
      const int listener = listen_tcp("127.0.0.1", 0, &port);
      const std::string address = "127.0.0.1:" + std::to_string(port);
      const PeerSecret secret = PeerSecret::random();
      auto child = std::make_unique<ChildProcess>(child_arguments(options, "--tcp", address),
                                                  child_environment(secret));
      ChildProcess* watched = child.get();
      const WaitPolicy policy = policy_with(options, watched);
      const int fd = accept_one(listener, policy, "TCP " + address);
      auto transport = std::make_unique<SocketTransport>(fd, policy, "TCP loopback");
      check_child(*transport, secret, address);
      return std::make_unique<ChildLink>(std::move(child), std::move(transport), nullptr,
                                         "TCP loopback " + address);
    }
  }
  throw RunError("unknown transport");
}

}  // namespace swarmnet
