// `swarmnet net`: the network half as a process of its own, reached by the robot half through
// a shared-memory segment, a Unix-domain socket or TCP (DESIGN.md section 3).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <string>

namespace swarmnet {

struct NetworkProcessOptions {
  std::string shm;     // attach to this segment (spawned by `swarmnet run`)
  std::string uds;     // connect to this Unix socket
  std::string tcp;     // connect to HOST:PORT
  std::string listen;  // accept one robot half on HOST:PORT (a network half on another host)
  pid_t parent = 0;    // stop as soon as this process is gone (0: no parent to watch)
  std::chrono::milliseconds step_timeout{std::chrono::seconds(60)};
  std::filesystem::path out;  // with --listen: where outputs go (default: the robot half's path)
};

// Serves one run. Returns the process exit status: 0 when the run finished, 1 otherwise; what
// went wrong has then been sent to the robot half, or printed when it could not be.
int run_network_process(const NetworkProcessOptions& options);

}  // namespace swarmnet
