// The network half's side of a run: receives each step's batch over the channel, simulates the
// step's window, returns the deliveries; on finish, returns its metrics. The same loop serves a
// thread (in-process transport) or a child process (shared memory, sockets).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "plugin/plugin_loader.hpp"
#include "protocol/step_channel.hpp"
#include "scenario/scenario.hpp"

namespace swarmnet {

// Who renames the network half's traces (packets.csv, frames.csv, sensing.csv) to their final
// names.
enum class TraceCommit : std::uint8_t {
  here,           // the network half, before it sends its report (a server's own directory)
  by_robot_half,  // the robot half, with the run's other outputs once the whole run succeeded;
                  // the network half leaves them finished and synced under NAME.partial-PID
};

// What the network half simulates and where it writes, decided from the robot half's hello: the
// scenario it validated, with the loader that resolved its plugins (used again to create them).
// A network half in its own process made that loader and owns it (`own_loader`); one in a thread
// borrows the robot half's, which outlives the thread.
struct NetworkSetup {
  Scenario scenario;
  std::filesystem::path run_dir;
  PluginLoader* loader = nullptr;
  std::unique_ptr<PluginLoader> own_loader;
  // A server's run (net --listen) ends on SIGTERM or SIGINT even mid-step, within a second; a
  // child of `swarmnet run` or a thread stops with its robot half instead.
  bool stops_on_signal = false;
  // A server's memory budget: one step's payloads may hold at most this many bytes (0: no
  // bound), and what an allocation failure is reported against ("the server's memory budget of
  // 4.0 GiB (--max-memory)").
  std::uint64_t step_payload_limit = 0;
  std::string memory_limit = "the host's memory";
  // A child or a thread writes into the robot half's own run directory, whose outputs the robot
  // half commits together; a server commits its traces in the directory it named itself.
  TraceCommit traces = TraceCommit::by_robot_half;
};

// What a network half simulating `scenario` says in its welcome.
Welcome welcome_for(const Scenario& scenario);

// Answers the handshake: reads the hello, decides the setup, builds the network engine (its
// fixed cost: a scenario that does not fit is refused here), then sends the welcome, or a
// failure with the reason. Then serves steps until the robot half sends finish, finishes the
// packet, frame and sensing traces in the run directory (when the scenario asks for them),
// committing them or not as NetworkSetup::traces says (a failed write is an error of the run,
// with the system's reason), and sends the report. On any error it tells the robot half why (a
// failure record), closes the channel and throws RunError. `welcomed`, when given, is set once the
// welcome is sent (the run began).
void serve_network_connection(StepChannel& channel,
                              const std::function<NetworkSetup(const Hello&)>& setup,
                              bool* welcomed = nullptr);

}  // namespace swarmnet
