// The network half's side of a run: receives each step's batch over the channel, simulates the
// step's window, returns the deliveries; on finish, returns its metrics. The same loop serves a
// thread (in-process transport) or a child process (shared memory, sockets).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>

#include "plugin/plugin_loader.hpp"
#include "protocol/step_channel.hpp"
#include "scenario/scenario.hpp"

namespace swarmnet {

// Who renames the network half's traces (packets.csv, frames.csv) to their final names.
enum class TraceCommit : std::uint8_t {
  here,           // the network half, before it sends its report (a server's own directory)
  by_robot_half,  // the robot half, with the run's other outputs once the whole run succeeded;
                  // the network half leaves them finished and synced under NAME.partial-PID
};

// Runs until the robot half sends finish, then finishes the packet and frame traces (when the
// scenario asks for them) in `run_dir`, committing them or not as `traces` says, and sends the
// report; a failed write is an error of the run, with the system's reason. Plugins come from
// `loader`, the one that resolved them when the scenario was validated. On any error it tells the
// robot half why (a failure record), closes the channel and throws RunError.
void serve_network_half(const Scenario& scenario, PluginLoader& loader, StepChannel& channel,
                        const std::filesystem::path& run_dir, TraceCommit traces);

// What the network half simulates and where it writes, decided from the robot half's hello: the
// scenario it validated, with the loader that resolved its plugins (used again to create them).
// A network half in its own process made that loader and owns it (`own_loader`); one in a thread
// borrows the robot half's, which outlives the thread.
struct NetworkSetup {
  Scenario scenario;
  std::filesystem::path run_dir;
  PluginLoader* loader = nullptr;
  std::unique_ptr<PluginLoader> own_loader;
};

// What a network half simulating `scenario` says in its welcome.
Welcome welcome_for(const Scenario& scenario);

// Answers the handshake (welcome, or failure with the reason), then serve_network_half().
void serve_network_connection(StepChannel& channel,
                              const std::function<NetworkSetup(const Hello&)>& setup);

}  // namespace swarmnet
