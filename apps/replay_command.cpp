#include "replay_command.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>

#include "outputs/output_files.hpp"
#include "session/replay.hpp"

namespace swarmnet {

namespace {

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

int replay_command(const ReplayCommandOptions& options) {
  ReplayInputs inputs;
  if (!options.run_dir.empty()) inputs = ReplayInputs::from_run_dir(options.run_dir);
  if (!options.scenario.empty()) inputs.scenario = options.scenario;
  if (!options.positions.empty()) inputs.positions = options.positions;
  if (!options.traffic.empty()) inputs.traffic = options.traffic;
  for (const auto* path : {&inputs.scenario, &inputs.positions, &inputs.traffic}) {
    if (path->empty() || !std::filesystem::is_regular_file(*path)) {
      std::fprintf(stderr,
                   "swarmnet: error: replay needs %s; give a run directory written with "
                   "output.mobility_trace and output.traffic_schedule on, or --scenario, "
                   "--positions and --traffic\n",
                   path->empty() ? "an input file" : ("'" + path->string() + "'").c_str());
      return 2;
    }
  }
  std::filesystem::path out = options.out;
  if (out.empty()) out = options.run_dir.empty() ? "replay" : options.run_dir / "replay";
  ReplayOutcome outcome;
  try {
    outcome = replay_network(inputs, out);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "swarmnet: error: %s\n", error.what());
    return 1;
  }
  const auto& s = outcome.summary;
  if (!options.quiet) {
    std::printf(
        "replayed the network half of '%s' (seed %s, %s robots, %s steps): %.3f CPU-s, "
        "%.1fx real time, unicast delivery ratio %.1f%%\n",
        s["scenario"].get<std::string>().c_str(), s["seed"].dump().c_str(),
        s["robots"].dump().c_str(), s["steps"].dump().c_str(), s["cpu_s"]["network"].get<double>(),
        s["realtime_factor"].get<double>(), 100.0 * s["pdr"].get<double>());
    std::string written = kPacketTraceFile;
    for (const char* file : {kFrameTraceFile, kSensingTraceFile}) {
      if (std::filesystem::exists(out / file)) written += std::string(", ") + file;
    }
    std::printf("  outputs  %s/ (%s, summary.json)\n", out.string().c_str(), written.c_str());
  }
  if (options.run_dir.empty()) return 0;
  // The run's traces that the replay wrote too must be its bytes (the replay's correctness check).
  const std::pair<const char*, const char*> checked[] = {{kPacketTraceFile, "packet trace"},
                                                         {kSensingTraceFile, "sensing trace"}};
  for (const auto& [file, what] : checked) {
    if (!std::filesystem::exists(options.run_dir / file)) continue;
    if (read_bytes(options.run_dir / file) != read_bytes(out / file)) {
      std::fprintf(stderr, "swarmnet: error: the replayed %s differs from %s\n", what,
                   (options.run_dir / file).string().c_str());
      return 1;
    }
    if (!options.quiet) std::printf("  %s is byte-identical to the run's\n", file);
  }
  return 0;
}

}  // namespace swarmnet
