// How the robot half reaches the network half for one run (DESIGN.md section 3):
//   shm     a child process (`swarmnet net`) over two rings in a shared-memory segment (default)
//   inproc  a thread of this process over the same rings in heap memory
//   uds     a child process over a Unix-domain socket
//   tcp     a child process over TCP loopback, or with a remote address a network half started
//           elsewhere with `swarmnet net --listen HOST:PORT`
// Every kind carries the same records, so every kind gives the same results.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "coupling/core_pairing.hpp"
#include "plugin/plugin_loader.hpp"
#include "scenario/scenario.hpp"
#include "transport.hpp"

namespace swarmnet {

enum class TransportKind : std::uint8_t { shm, inproc, uds, tcp };

const char* to_string(TransportKind kind);
std::optional<TransportKind> parse_transport_kind(std::string_view text);

struct LinkOptions {
  TransportKind kind = TransportKind::shm;
  std::string remote;      // "tcp://HOST:PORT" of a listening network half; empty: spawn a child
  std::string token_file;  // with `remote`: the token it was started with (else from the env)
  std::chrono::milliseconds step_timeout{std::chrono::seconds(60)};
  std::uint64_t ring_bytes = std::uint64_t{1} << 22U;  // per direction, shm and inproc
};

class NetworkLink {
 public:
  NetworkLink() = default;
  NetworkLink(const NetworkLink&) = delete;
  NetworkLink& operator=(const NetworkLink&) = delete;
  NetworkLink(NetworkLink&&) = delete;
  NetworkLink& operator=(NetworkLink&&) = delete;
  virtual ~NetworkLink() = default;

  virtual Transport& transport() = 0;
  [[nodiscard]] virtual std::string describe() const = 0;
  // The process of a network half that writes its traces into this run's directory and leaves
  // them, finished under NAME.partial-PID, for this half to commit with the run's other outputs:
  // a child's pid, this process's for a thread; 0 for a remote one (it commits on its own host).
  [[nodiscard]] virtual pid_t local_network_pid() const = 0;
  // The thread that runs a local network half, for keeping it beside the robot half
  // (core_pairing.hpp); {0, 0} for a remote one.
  [[nodiscard]] virtual ThreadId network_thread() const = 0;
  // The handshake succeeded: nothing more needs a name on the file system.
  virtual void connected() {}
  // After the robot half closed its end: waits a short while for the network half to stop (then
  // stops it) and says what went wrong with it, or "" if it ended cleanly.
  virtual std::string finish() = 0;
};

// "HOST:PORT" (HOST may be [v6]) split; throws RunError on a malformed address.
std::pair<std::string, std::uint16_t> parse_host_port(const std::string& text);

// Starts the network half for `scenario` (thread or child process) or connects to a remote one.
// A thread creates its plugins with `loader` (the robot half's, done with it by then); a process
// validates the scenario it is sent and resolves its own. Throws TransportError or RunError.
std::unique_ptr<NetworkLink> open_network_link(const Scenario& scenario, PluginLoader& loader,
                                               const std::filesystem::path& run_dir,
                                               const LinkOptions& options);

}  // namespace swarmnet
