// Helpers for the network half's tests: scenarios built by hand, batches, runs, trace parsing.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "network/network_settings.hpp"
#include "plugin/plugin_loader.hpp"
#include "protocol/step_data.hpp"
#include "swarmnet/params.hpp"

namespace swarmnet::test {

// A plugin choice with the plugin's default parameters.
PluginChoice choose(PluginLoader& loader, const std::string& name, PluginKind kind);
// Overrides one parameter; fails the test if the plugin does not declare it.
void set_param(PluginChoice& choice, const std::string& name, ParamValue value);

// `robots` robots in a 1000 x 1000 m arena, disk propagation (default range 120 m), the given
// MAC and routing with default parameters, seed 1, 0.1 s steps.
NetworkSettings make_settings(PluginLoader& loader, std::uint32_t robots,
                              const std::string& mac = "ideal_mac",
                              const std::string& routing = "flooding");

// Robots on the x axis at y = 50, `spacing_m` apart, starting at x = 10.
std::vector<Vec2> line_positions(std::uint32_t robots, double spacing_m);

AppMessage message(std::uint64_t id, RobotId source, RobotId destination,
                   std::size_t payload_bytes = 100);

// Batches for `steps` steps with fixed positions; `messages` go into step 0.
std::vector<StepBatch> fixed_batches(const NetworkSettings& settings,
                                     const std::vector<Vec2>& positions, std::uint64_t steps,
                                     std::vector<AppMessage> messages);

// Random motion and traffic: robots start uniformly in the arena and random-walk up to `move_m`
// per step; each step carries `messages_per_step` messages from random sources, a fraction
// `broadcast_fraction` of them broadcast, payloads of 16..256 bytes.
std::vector<StepBatch> random_batches(const NetworkSettings& settings, std::uint64_t traffic_seed,
                                      std::uint64_t steps, std::uint32_t messages_per_step,
                                      double broadcast_fraction, double move_m);

struct RunOutput {
  std::string trace;
  std::vector<Delivery> deliveries;
  std::vector<std::uint64_t> events_per_step;
  nlohmann::ordered_json report;
};

// A whole run: constructs a NetworkSimulator, runs every batch, finishes; appends every step's
// send reports to `send_reports` if given.
RunOutput run(const NetworkSettings& settings, PluginLoader& loader,
              const std::vector<StepBatch>& batches,
              std::vector<AddressedSendReport>* send_reports = nullptr);

struct TraceLine {
  std::int64_t time_ns = 0;
  std::string event;
  std::int64_t node = 0;
  std::uint64_t uid = 0;
  std::string message_id;
  std::int64_t source = 0;
  std::int64_t destination = 0;
  std::uint32_t hops = 0;
  std::uint32_t bytes = 0;
  std::string detail;
};

// Parses a packet trace; fails the test if the header or a line is malformed.
std::vector<TraceLine> parse_trace(const std::string& text);

// How many trace lines have this event at this node.
std::size_t count_events(const std::vector<TraceLine>& lines, const std::string& event,
                         std::int64_t node);

}  // namespace swarmnet::test
