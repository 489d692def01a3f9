// The network half's side of a run: receives each step's batch over the channel, simulates the
// step's window, returns the deliveries; on finish, returns its metrics. The same loop serves a
// thread (in-process transport) or a child process (shared memory, sockets).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>

#include "plugin/plugin_loader.hpp"
#include "protocol/step_channel.hpp"
#include "scenario/scenario.hpp"

namespace swarmnet {

// Runs until the robot half sends finish, then commits the packet trace (when the scenario asks
// for one) into `run_dir` and sends the report. Plugins come from `loader`, the one that resolved
// them when the scenario was validated. On any error it tells the robot half why (a failure
// record), closes the channel and throws RunError.
// With `stops_on_signal`, a stop signal (stop_signal.hpp) ends the run within a second, between
// steps or inside one, with a failure naming the signal.
void serve_network_half(const Scenario& scenario, PluginLoader& loader, StepChannel& channel,
                        const std::filesystem::path& run_dir, bool stops_on_signal = false);

// What the network half simulates and where it writes, decided from the robot half's hello: the
// scenario it validated, with the loader that resolved its plugins (used again to create them).
// A network half in its own process made that loader and owns it (`own_loader`); one in a thread
// borrows the robot half's, which outlives the thread.
struct NetworkSetup {
  Scenario scenario;
  std::filesystem::path run_dir;
  PluginLoader* loader = nullptr;
  std::unique_ptr<PluginLoader> own_loader;
  // A server's run (net --listen) ends on SIGTERM or SIGINT even mid-step; a child of
  // `swarmnet run` or a thread stops with its robot half instead.
  bool stops_on_signal = false;
};

// What a network half simulating `scenario` says in its welcome.
Welcome welcome_for(const Scenario& scenario);

// Answers the handshake (welcome, or failure with the reason), then serve_network_half().
void serve_network_connection(StepChannel& channel,
                              const std::function<NetworkSetup(const Hello&)>& setup);

}  // namespace swarmnet
