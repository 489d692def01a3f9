// `swarmnet replay RUN_DIR [--out DIR]`, or from explicit files
// (`--scenario F --positions F --traffic F --out DIR`): the network half alone (run/replay.hpp).
#pragma once

#include <filesystem>

namespace swarmnet {

struct ReplayCommandOptions {
  std::filesystem::path run_dir;    // "" when the files are given one by one
  std::filesystem::path scenario;   // overrides RUN_DIR/scenario.resolved.yaml
  std::filesystem::path positions;  // overrides RUN_DIR/positions.bin
  std::filesystem::path traffic;    // overrides RUN_DIR/traffic.csv
  std::filesystem::path out;        // default RUN_DIR/replay
  bool quiet = false;
};

// Exit code: 0 (and, with a RUN_DIR holding packets.csv, the replayed trace is byte-identical to
// it), 1 the replay failed or its trace differs, 2 bad input.
int replay_command(const ReplayCommandOptions& options);

}  // namespace swarmnet
