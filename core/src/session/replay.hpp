// The network half alone (DESIGN.md section 2, `swarmnet replay`): from a run's exact positions
// (positions.bin), its traffic schedule (traffic.csv, with send_options.csv and
// route_queries.csv beside it when the run wrote them) and its resolved scenario, feed the network
// simulator step by step exactly as the integrated run did, and write the same packet trace (and
// the same sensing trace, when the scenario has output.sensing_trace).
//
// Payload contents are not recorded (traffic.csv has sizes only) and do not affect the network
// half: replayed messages carry zero bytes of the recorded size.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

namespace swarmnet {

struct ReplayInputs {
  std::filesystem::path scenario;   // scenario.resolved.yaml
  std::filesystem::path positions;  // positions.bin
  // traffic.csv; send_options.csv and route_queries.csv beside it are read if present
  std::filesystem::path traffic;
  // The inputs of the run in `run_dir` (its resolved scenario, positions.bin and traffic.csv).
  static ReplayInputs from_run_dir(const std::filesystem::path& run_dir);
};

struct ReplayOutcome {
  std::filesystem::path dir;
  nlohmann::ordered_json summary;
};

// Replays into `out_dir` (created): packets.csv (frames.csv and sensing.csv when the scenario
// asks for them), then summary.json (network metrics, wall time,
// CPU time of the network half alone). Throws RunError or ScenarioError naming the file at fault.
ReplayOutcome replay_network(const ReplayInputs& inputs, const std::filesystem::path& out_dir);

}  // namespace swarmnet
