#include "coupling/network_process.hpp"

#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>

#include "coupling/handshake_acceptor.hpp"
#include "coupling/memory_budget.hpp"
#include "coupling/network_half.hpp"
#include "coupling/network_link.hpp"
#include "coupling/peer_authentication.hpp"
#include "coupling/peer_cpu.hpp"
#include "coupling/stop_signal.hpp"
#include "outputs/run_error.hpp"
#include "plugin/plugin_loader.hpp"
#include "protocol/step_channel.hpp"
#include "ring_transport.hpp"
#include "scenario/scenario_loader.hpp"
#include "shm_segment.hpp"
#include "socket_transport.hpp"

namespace swarmnet {

namespace {

// The largest record a server takes from a peer before the handshake is done: a hello with the
// largest scenario text a record may carry.
constexpr std::uint32_t kHandshakeRecordBytes = kMaxTextBytes + (1U << 16U);

void say(const std::string& text) { std::fprintf(stderr, "swarmnet net: %s\n", text.c_str()); }

struct Connection {
  std::unique_ptr<ShmSegment> segment;  // kept mapped for the transport's lifetime
  std::unique_ptr<Transport> transport;
};

// The secret a robot half handed its child for a socket link.
PeerSecret child_secret() {
  const char* hex = std::getenv(kChildSecretVariable);
  if (hex == nullptr) {
    throw RunError(std::string("started without ") + kChildSecretVariable +
                   ": a socket child is started by 'swarmnet run', which hands it the secret");
  }
  return PeerSecret::from_hex(hex);
}

// A child of `swarmnet run`: attach or connect to what the parent opened.
Connection connect_child(const NetworkProcessOptions& options, const WaitPolicy& policy) {
  Connection c;
  if (!options.shm.empty()) {
    c.segment = ShmSegment::attach(options.shm);
    c.transport = std::make_unique<RingTransport>(
        c.segment->network_to_robot(), c.segment->robot_to_network(), policy, "shared memory");
    return c;
  }
  const PeerSecret secret = child_secret();
  if (!options.uds.empty()) {
    c.transport =
        std::make_unique<SocketTransport>(connect_unix(options.uds), policy, "Unix-domain socket");
  } else {
    const auto [host, port] = parse_host_port(options.tcp);
    c.transport = std::make_unique<SocketTransport>(connect_tcp(host, port), policy, "TCP");
  }
  if (std::string why = authenticate_to_acceptor(*c.transport, secret); !why.empty()) {
    throw RunError(why);
  }
  return c;
}

int serve_parent(const NetworkProcessOptions& options) {
  // Ctrl-C reaches the whole process group: the robot half decides when the run stops.
  if (options.parent != 0) {
    ::signal(SIGINT, SIG_IGN);
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != options.parent) return 1;  // the parent died before we got here
  }
  WaitPolicy policy;
  policy.timeout = options.step_timeout;
  if (options.parent != 0) {
    const pid_t parent = options.parent;
    policy.peer_alive = [parent] { return ::getppid() == parent; };
    // A robot half computing a long step (physics of thousands of robots) is not hung.
    policy.peer_cpu = [parent] { return process_cpu_time(parent); };
  }
  Connection connection;
  try {
    connection = connect_child(options, policy);
  } catch (const std::exception& error) {
    say(std::string("error: ") + error.what());
    return 1;
  }
  StepChannel channel(*connection.transport, "the robot half");
  try {
    // The parent's own scenario, plugin paths and run directory: it started this process.
    serve_network_connection(channel, [&](const Hello& hello) {
      auto loader = std::make_unique<PluginLoader>();
      Scenario scenario =
          load_scenario_text(hello.scenario_yaml, "the robot half's scenario", *loader);
      PluginLoader* resolved = loader.get();
      return NetworkSetup{std::move(scenario), std::filesystem::path(hello.run_dir), resolved,
                          std::move(loader)};
    });
  } catch (const std::exception& error) {
    // Already sent to the robot half, which reports it; printed too for anyone watching.
    if (options.parent == 0) say(std::string("error: ") + error.what());
    return 1;
  }
  return 0;
}

// "[HOST:]PORT"; HOST defaults to loopback.
std::pair<std::string, std::uint16_t> listen_address(const std::string& text) {
  if (text.find(':') == std::string::npos) return parse_host_port("127.0.0.1:" + text);
  return parse_host_port(text);
}

// A directory only this user may use: created 0700, or an existing one that is ours and that no
// one else may enter (the runs of every peer are written there).
void make_private_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  const bool existed = std::filesystem::exists(dir, ec);
  std::filesystem::create_directories(dir, ec);
  if (ec) throw RunError("cannot create " + dir.string() + ": " + ec.message());
  if (!existed && ::chmod(dir.c_str(), 0700) != 0) {
    throw RunError("cannot make " + dir.string() + " private: " + std::strerror(errno));
  }
  struct stat info {};
  if (::stat(dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)) {
    throw RunError(dir.string() + " is not a directory");
  }
  if (info.st_uid != ::geteuid()) throw RunError(dir.string() + " belongs to another user");
  if ((info.st_mode & 077U) != 0) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", info.st_mode & 07777U);
    throw RunError(dir.string() + " may be entered by other users (mode " + mode +
                   "); make it private with 'chmod 700 " + dir.string() +
                   "' or choose another --out");
  }
}

// OUT/run-NNNN, the first number not taken: named by the server, never by the peer.
std::filesystem::path next_run_dir(const std::filesystem::path& out) {
  for (unsigned n = 1;; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "run-%04u", n);
    const std::filesystem::path dir = out / name;
    if (::mkdir(dir.c_str(), 0700) == 0) return dir;
    if (errno != EEXIST)
      throw RunError("cannot create " + dir.string() + ": " + std::strerror(errno));
  }
}

// `message` with every directory of this host that the peer has no business knowing replaced.
std::string redact(std::string message, const std::vector<std::filesystem::path>& private_dirs) {
  for (const auto& dir : private_dirs) {
    const std::string text = dir.string();
    if (text.empty() || text == "/") continue;
    for (std::size_t at = message.find(text); at != std::string::npos;
         at = message.find(text, at)) {
      message.replace(at, text.size(), "<network half's host>");
    }
  }
  return message;
}

// What a remote robot half's hello asks this server to simulate: its scenario, parsed once, with
// the server's own plugin search path and run directory set on the typed settings (the text's
// plugin_paths is never read, whatever its spelling; a repeated key is refused). Errors reach the
// peer with this host's paths redacted.
NetworkSetup remote_setup(const Hello& hello, const NetworkProcessOptions& options,
                          const std::filesystem::path& out) {
  auto loader = std::make_unique<PluginLoader>(options.plugin_paths);
  std::vector<std::filesystem::path> private_dirs = loader->search_path();
  private_dirs.push_back(out);
  try {
    Scenario scenario = load_peer_scenario_text(hello.scenario_yaml, "the robot half's scenario",
                                                *loader, options.plugin_paths);
    PluginLoader* resolved = loader.get();
    NetworkSetup setup{std::move(scenario), next_run_dir(out), resolved, std::move(loader)};
    setup.scenario.output.dir = setup.run_dir;
    setup.stops_on_signal = true;
    setup.traces = TraceCommit::here;
    setup.step_payload_limit = options.max_memory / 4;
    setup.memory_limit =
        "the server's memory budget of " + describe_bytes(options.max_memory) + " (--max-memory)";
    return setup;
  } catch (const std::exception& error) {
    say(std::string("refused a scenario: ") + error.what());
    throw RunError(redact(error.what(), private_dirs));
  }
}

int serve_remote(const NetworkProcessOptions& options) {
  const std::filesystem::path token = token_file_from(options.token_file);
  if (token.empty()) {
    throw RunError(std::string("--listen needs a token that robot halves must prove they "
                               "know: --token-file FILE or ") +
                   kTokenFileVariable + " (docs/security.md)");
  }
  const PeerSecret secret = PeerSecret::from_file(token);
  const std::filesystem::path out = options.out.empty() ? private_output_dir() : options.out;
  make_private_directory(out);
  // Before any thread starts: a handshake needs little stack (an HMAC), so the server's threads
  // get 256 KiB each instead of the 8 MiB default; their reserved stacks are counted apart from
  // the budget.
  constexpr std::uint64_t kThreadStackBytes = std::uint64_t{256} << 10U;
  pthread_attr_t thread_defaults;
  // (Under AddressSanitizer no limit is set, and its larger frames keep the default stacks.)
  if (kernel_memory_limit_available() && ::pthread_attr_init(&thread_defaults) == 0) {
    if (::pthread_attr_setstacksize(&thread_defaults, kThreadStackBytes) == 0) {
      ::pthread_setattr_default_np(&thread_defaults);
    }
    ::pthread_attr_destroy(&thread_defaults);
  }
  limit_process_memory(MemoryBudget{options.max_memory},
                       (std::uint64_t{options.max_pending_handshakes} + 4) * kThreadStackBytes);
  const auto [host, port] = listen_address(options.listen);
  std::uint16_t bound = 0;
  const int listener = listen_tcp(host, port, &bound, SOMAXCONN);
  say("serving robot halves on " + host + ":" + std::to_string(bound) + ", runs in " +
      out.string() +
      (options.serve_forever ? ", until stopped"
                             : ", " + std::to_string(options.runs) + " run(s)") +
      ", memory budget " + describe_bytes(options.max_memory) +
      (kernel_memory_limit_available() ? ""
                                       : " (not enforced by the kernel under AddressSanitizer)"));
  HandshakeSettings handshakes;
  handshakes.deadline = options.handshake_timeout;
  handshakes.max_pending = options.max_pending_handshakes;
  handshakes.max_record_bytes = kHandshakeRecordBytes;
  handshakes.policy.timeout = options.step_timeout;
  handshakes.policy.peer_alive = [] { return stop_signal() == 0; };
  HandshakeAcceptor door(listener, "TCP " + host + ":" + std::to_string(bound), secret, handshakes,
                         &say);

  int status = 0;
  for (std::uint32_t served = 0; options.serve_forever || served < options.runs;) {
    std::optional<AuthenticatedPeer> next = door.next([] { return stop_signal() != 0; });
    if (!next) break;
    SocketTransport& transport = *next->transport;
    const std::string& peer = next->address;
    // It may have waited behind a run: the hello gets a deadline of its own.
    transport.set_deadline(std::chrono::steady_clock::now() + options.handshake_timeout);
    StepChannel channel(transport, "the robot half at " + peer);
    bool accepted = false;  // welcomed: a refused scenario does not use up one of --runs
    try {
      serve_network_connection(
          channel,
          [&](const Hello& hello) {
            transport.clear_deadline();
            transport.set_max_record_bytes(SocketTransport::kMaxRecordBytes);
            NetworkSetup setup = remote_setup(hello, options, out);
            say("run " + setup.run_dir.filename().string() + " for " + peer + ": " +
                std::to_string(setup.scenario.robots.count) + " robots");
            return setup;
          },
          &accepted);
      say("finished the run for " + peer);
    } catch (const std::exception& error) {
      say("the run for " + peer + " failed: " + error.what());
      if (accepted) status = 1;
    }
    if (accepted) {
      ++served;
      say("idle; " + describe_bytes(return_free_memory()) + " resident");
    }
  }
  if (stop_signal() != 0) say(std::string("stopped by ") + stop_signal_name(stop_signal()));
  return status;
}

}  // namespace

std::filesystem::path private_output_dir() {
  if (const char* state = std::getenv("XDG_STATE_HOME"); state != nullptr && *state == '/') {
    return std::filesystem::path(state) / "swarmnet" / "net";
  }
  const char* home = std::getenv("HOME");
  if (home == nullptr || *home != '/') {
    throw RunError("no --out given and neither XDG_STATE_HOME nor HOME is set");
  }
  return std::filesystem::path(home) / ".local" / "state" / "swarmnet" / "net";
}

int run_network_process(const NetworkProcessOptions& options) {
  if (options.listen.empty()) return serve_parent(options);
  try {
    return serve_remote(options);
  } catch (const std::exception& error) {
    say(std::string("error: ") + error.what());
    return 1;
  }
}

}  // namespace swarmnet
