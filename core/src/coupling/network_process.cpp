#include "coupling/network_process.hpp"

#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cstdio>
#include <memory>

#include "coupling/network_half.hpp"
#include "coupling/network_link.hpp"
#include "outputs/run_error.hpp"
#include "plugin/plugin_loader.hpp"
#include "protocol/step_channel.hpp"
#include "ring_transport.hpp"
#include "scenario/scenario_loader.hpp"
#include "shm_segment.hpp"
#include "socket_transport.hpp"

namespace swarmnet {

namespace {

struct Connection {
  std::unique_ptr<ShmSegment> segment;  // kept mapped for the transport's lifetime
  std::unique_ptr<Transport> transport;
};

Connection connect(const NetworkProcessOptions& options, const WaitPolicy& policy) {
  Connection c;
  if (!options.shm.empty()) {
    c.segment = ShmSegment::attach(options.shm);
    c.transport = std::make_unique<RingTransport>(
        c.segment->network_to_robot(), c.segment->robot_to_network(), policy, "shared memory");
  } else if (!options.uds.empty()) {
    c.transport =
        std::make_unique<SocketTransport>(connect_unix(options.uds), policy, "Unix-domain socket");
  } else if (!options.tcp.empty()) {
    const auto [host, port] = parse_host_port(options.tcp);
    c.transport = std::make_unique<SocketTransport>(connect_tcp(host, port), policy, "TCP");
  } else if (!options.listen.empty()) {
    const auto [host, port] = parse_host_port(options.listen);
    std::uint16_t bound = 0;
    const int listener = listen_tcp(host, port, &bound);
    std::fprintf(stderr, "swarmnet net: waiting for a robot half on %s:%u\n", host.c_str(),
                 static_cast<unsigned>(bound));
    WaitPolicy patient = policy;
    patient.timeout = std::chrono::hours(24 * 365);  // a server waits for its client
    const int fd = accept_one(listener, patient, "TCP " + options.listen);
    c.transport = std::make_unique<SocketTransport>(fd, policy, "TCP");
  } else {
    throw RunError("swarmnet net needs one of --shm, --uds, --tcp or --listen");
  }
  return c;
}

}  // namespace

int run_network_process(const NetworkProcessOptions& options) {
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
  }
  Connection connection;
  try {
    connection = connect(options, policy);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "swarmnet net: error: %s\n", error.what());
    return 1;
  }
  StepChannel channel(*connection.transport, "the robot half");
  try {
    serve_network_connection(channel, [&](const Hello& hello) {
      PluginLoader loader;
      NetworkSetup setup{
          load_scenario_text(hello.scenario_yaml, "the robot half's scenario", loader),
          options.out.empty() ? std::filesystem::path(hello.run_dir) : options.out};
      if (!options.out.empty()) std::filesystem::create_directories(setup.run_dir);
      return setup;
    });
  } catch (const std::exception& error) {
    // Already sent to the robot half; printed too when nobody started us to read it.
    if (options.parent == 0) std::fprintf(stderr, "swarmnet net: error: %s\n", error.what());
    return 1;
  }
  return 0;
}

}  // namespace swarmnet
