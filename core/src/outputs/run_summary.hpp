// summary.json (DESIGN.md section 6), built in one place for a run and for a replay: the same
// keys in the same order, with the parts only one of them has.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "protocol/network_report.hpp"
#include "robot/controller_metrics.hpp"
#include "scenario/scenario.hpp"

namespace swarmnet {

// Timing of a run: wall time and CPU per half (those a replay does not have are absent).
struct RunTimings {
  double wall_s = 0.0;
  std::optional<double> robot_cpu_s;
  double network_cpu_s = 0.0;
  std::optional<double> transport_cpu_s;
};

// The files of the run directory that summary.json lists, by their role.
using OutputList = std::map<std::string, std::string>;

struct SummaryInputs {
  const Scenario* scenario = nullptr;
  // A replay names what it replayed instead of the scenario file it came from.
  struct ReplayOf {
    std::filesystem::path scenario, positions, traffic;
  };
  std::optional<ReplayOf> replay_of;
  std::optional<std::string> transport;  // a run's transport ("shm", or the remote address)
  RunTimings timings;
  const NetworkReport* network = nullptr;
  // Controllers' metrics by name (a run only).
  const ControllerMetrics* controllers = nullptr;
  // World plugins' metrics by name (a run with world plugins only).
  const ControllerMetrics* world = nullptr;
  // Steps simulated, when not the scenario's step_count() (a world ended the run early, or a
  // replay of such a run).
  std::optional<std::uint64_t> steps;
  // How a run ended: by a world plugin's task_done() (named), or at duration_s (none).
  struct Ended {
    std::optional<std::string> by_world;
  };
  std::optional<Ended> ended;
};

// The network half's part of summary.json: packets, pdr, delay_s, hops_mean, mac, routing,
// events (definitions: network/network_metrics.hpp).
nlohmann::ordered_json network_report_json(const NetworkReport& report);

// The whole summary.json of a run or a replay, the scenario's outputs listed under "outputs".
nlohmann::ordered_json build_summary(const SummaryInputs& inputs);

}  // namespace swarmnet
